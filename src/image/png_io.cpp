#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>

#include <sys/stat.h>
#include <unistd.h>

namespace illum {
namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& image) {
  std::vector<std::uint8_t> out;
  if (!stbi_write_png_to_func(appendBytes, &out, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4))
    throw Error("cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " PNG");
  return out;
}

void writePng(const std::filesystem::path& path, const Image& image) {
  writeOutputFile(path, encodePng(image));
}

Image readPng(const std::filesystem::path& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) throw InputError(path.string() + ": cannot read the image: " + stbi_failure_reason());
  Image img(w, h);
  std::memcpy(img.rgba.data(), data, img.rgba.size());
  stbi_image_free(data);
  return img;
}

}  // namespace illum
