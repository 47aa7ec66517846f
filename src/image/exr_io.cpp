// OpenEXR output (Debian's libopenexr): linear float channels, unclamped, as the ray and path
// tracers computed them. Encoded in memory so that writeOutputFile can put it in place safely.
#include <illum/error.h>
#include <illum/image.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cstring>
#include <exception>
#include <string>

namespace illum {
namespace {

// An Imf::OStream into a byte vector.
class MemoryStream final : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + std::size_t(n) > bytes_.size()) bytes_.resize(position_ + std::size_t(n));
    std::memcpy(bytes_.data() + position_, c, std::size_t(n));
    position_ += std::size_t(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = std::size_t(pos); }
  std::vector<std::uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t position_ = 0;
};

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

// Channel c of a layer of `channels`: R, G, B (, A), or Z alone (a depth, as OpenEXR names it).
const char* channelName(int c, int channels) { return channels == 1 ? "Z" : kChannelNames[c]; }

// The slices of `channels` interleaved floats per pixel, named `prefix` + their channel's name.
void insertSlices(Imf::FrameBuffer& fb, const std::string& prefix, const float* base, int channels, int width) {
  const std::size_t pixel = std::size_t(channels) * sizeof(float), row = pixel * std::size_t(width);
  for (int c = 0; c < channels; ++c)
    fb.insert(prefix + channelName(c, channels),
              Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(base + c)), pixel, row));
}

Imf::FrameBuffer frameBuffer(const float* base, int width) {
  Imf::FrameBuffer fb;
  insertSlices(fb, "", base, 4, width);
  return fb;
}

}  // namespace

std::vector<std::uint8_t> encodeExr(const FloatImage& image) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* name : kChannelNames) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer fb = frameBuffer(image.rgba.data(), image.width);
  for (const FloatLayer& layer : image.layers) {
    for (int c = 0; c < layer.channels; ++c)
      header.channels().insert(layer.name + "." + channelName(c, layer.channels), Imf::Channel(Imf::FLOAT));
    insertSlices(fb, layer.name + ".", layer.values.data(), layer.channels, image.width);
  }
  MemoryStream stream;
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(fb);
    file.writePixels(image.height);
  }
  return stream.take();
}

FloatImage readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    FloatImage image;
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    image.rgba.assign(std::size_t(image.width) * std::size_t(image.height) * 4, 0.0f);
    // The frame buffer is addressed from the data window's origin.
    const std::ptrdiff_t origin = (std::ptrdiff_t(window.min.y) * image.width + window.min.x) * 4;
    file.setFrameBuffer(frameBuffer(image.rgba.data() - origin, image.width));
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw InputError(path.string() + ": cannot read the OpenEXR file: " + e.what());
  }
}

}  // namespace illum
