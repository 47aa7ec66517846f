#include <illum/image.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include <unistd.h>

namespace illum {
namespace {

// What is encoded decodes to the same bytes (through stb_image, an independent decoder), for odd
// sizes, one-pixel images and noise that the sub filter cannot flatten.
TEST(PngIo, EncodeDecodeRoundTripIsExact) {
  std::mt19937 random(7);
  const auto path = std::filesystem::temp_directory_path() / ("illum_png_" + std::to_string(::getpid()) + ".png");
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{257, 31}, std::pair{64, 64}}) {
    Image image(w, h);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(random() & 0xff);
    writePng(path, image);
    const Image back = readPng(path);
    EXPECT_EQ(back.width, w);
    EXPECT_EQ(back.height, h);
    EXPECT_EQ(back.rgba, image.rgba) << w << "x" << h;
  }
  std::filesystem::remove(path);
}

TEST(PngIo, SmoothPicturesCompress) {
  Image image(512, 256);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = std::uint8_t(x / 2), p[1] = std::uint8_t(y), p[2] = 128, p[3] = 255;
    }
  EXPECT_LT(encodePng(image).size(), image.rgba.size() / 20);
}

}  // namespace
}  // namespace illum
