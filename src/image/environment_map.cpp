#include <illum/environment.h>
#include <illum/error.h>

#include "core/input_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>

namespace illum {
namespace {

// stb_image keeps its reason in a global: good enough for a message, which is all it is used for.
std::string stbReason() {
  const char* r = stbi_failure_reason();
  return r ? r : "unknown reason";
}

// A cursor over a Radiance file's bytes that refuses to read past the end.
class HdrReader {
 public:
  HdrReader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}
  // The next header line, without its '\n'.
  std::string line() {
    const std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string::npos) fail("the header ends without the line that gives the size");
    std::string l = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return l;
  }
  unsigned byte() {
    if (pos_ >= bytes_.size()) cutShort();
    return static_cast<unsigned char>(bytes_[pos_++]);
  }
  void skip(std::size_t n) {
    if (bytes_.size() - pos_ < n) cutShort();
    pos_ += n;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(name_ + ": not a Radiance .hdr environment map that can be read: " + why);
  }

 private:
  [[noreturn]] void cutShort() const { fail("the pixel data is cut short (a truncated file?)"); }
  const std::string& bytes_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

// OpenEXR's magic number: the first four bytes of every EXR file.
bool isOpenExr(const std::string& bytes) {
  return bytes.size() >= 4 && std::uint8_t(bytes[0]) == 0x76 && std::uint8_t(bytes[1]) == 0x2f &&
         std::uint8_t(bytes[2]) == 0x31 && std::uint8_t(bytes[3]) == 0x01;
}

// An Imf::IStream over bytes already read through the input gate.
class ExrBytes final : public Imf::IStream {
 public:
  ExrBytes(const std::string& bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || position_ + std::uint64_t(n) > bytes_.size()) throw std::runtime_error("the file ends early");
    std::memcpy(c, bytes_.data() + position_, std::size_t(n));
    position_ += std::uint64_t(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = pos; }

 private:
  const std::string& bytes_;
  std::uint64_t position_ = 0;
};

// An OpenEXR map's size from its header, refused unless it has R, G and B channels and at most
// limits.maxPixels pixels (checked before any pixel is read).
HdrSize checkOpenExrHeader(const Imf::Header& header, const std::string& name, const Limits& limits) {
  const Imath::Box2i window = header.dataWindow();
  const std::int64_t w = std::int64_t(window.max.x) - window.min.x + 1, h = std::int64_t(window.max.y) - window.min.y + 1;
  if (w <= 0 || h <= 0) throw InputError(name + ": an OpenEXR environment map of no pixels");
  if (std::uint64_t(w) * std::uint64_t(h) > limits.maxPixels)
    throw InputError(name + ": an OpenEXR environment map of " + std::to_string(w) + "×" + std::to_string(h) +
                     " pixels, more than the limit of " + std::to_string(limits.maxPixels) + " (raise it with --max-pixels)");
  for (const char* c : {"R", "G", "B"})
    if (!header.channels().findChannel(c))
      throw InputError(name + ": an OpenEXR environment map needs R, G and B channels; it has no " + c);
  return {int(w), int(h)};
}

HdrSize checkOpenExr(const std::string& bytes, const std::string& name, const Limits& limits) {
  try {
    ExrBytes stream(bytes, name);
    Imf::InputFile file(stream);
    return checkOpenExrHeader(file.header(), name, limits);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name + ": not a readable OpenEXR image: " + e.what());
  }
}

// The map's R, G and B as floats, rows top to bottom.
std::shared_ptr<const float> decodeOpenExr(const std::string& bytes, const std::string& name, const Limits& limits,
                                           HdrSize& size) {
  try {
    ExrBytes stream(bytes, name);
    Imf::InputFile file(stream);
    size = checkOpenExrHeader(file.header(), name, limits);
    const Imath::Box2i window = file.header().dataWindow();
    std::shared_ptr<float> rgb(new float[3 * std::size_t(size.width) * std::size_t(size.height)](),
                               std::default_delete<float[]>());
    Imf::FrameBuffer frame;
    // Slices addressed from the data window's origin, as OpenEXR expects.
    char* origin = reinterpret_cast<char*>(rgb.get()) -
                   (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * size.width) * std::ptrdiff_t(3 * sizeof(float));
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), 3 * sizeof(float),
                                        std::size_t(3) * sizeof(float) * std::size_t(size.width)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    float* p = rgb.get();
    for (std::size_t i = 0; i < 3 * std::size_t(size.width) * std::size_t(size.height); ++i)
      if (!std::isfinite(p[i]) || p[i] < 0) p[i] = 0;  // radiance is finite and never negative
    return rgb;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name + ": cannot decode the OpenEXR environment map: " + e.what());
  }
}

}  // namespace

HdrSize checkRadianceHdr(const std::string& bytes, const std::string& name, const Limits& limits) {
  HdrReader in(bytes, name);
  // ---- Header: identifier, variables up to an empty line, then "-Y height +X width" ----
  // (The format is the content's, whatever the name says: a file that begins as neither is
  // refused as neither.)
  if (bytes.compare(0, 2, "#?") != 0)
    throw InputError(name + ": neither an OpenEXR image (whose first four bytes are 76 2f 31 01) nor a Radiance .hdr one "
                            "(whose first line is #?RADIANCE or #?RGBE)");
  const std::string magic = in.line();
  if (magic != "#?RADIANCE" && magic != "#?RGBE") in.fail("expected #?RADIANCE or #?RGBE on its first line");
  bool rgbe = false;
  for (std::string l = in.line(); !l.empty(); l = in.line()) rgbe = rgbe || l == "FORMAT=32-bit_rle_rgbe";
  if (!rgbe) in.fail("expected FORMAT=32-bit_rle_rgbe (the only format of light probes it reads)");
  const std::string resolution = in.line();
  long height = 0, width = 0;
  char end = 0;
  const int read = std::sscanf(resolution.c_str(), "-Y %ld +X %ld%c", &height, &width, &end);
  if (read < 2 || (read == 3 && !std::isspace(static_cast<unsigned char>(end))))
    in.fail("expected the size as \"-Y height +X width\" (rows from the top), got \"" + resolution.substr(0, 40) + "\"");
  if (width < 1 || height < 1)
    in.fail("the map has no pixels (" + std::to_string(width) + "×" + std::to_string(height) + ")");
  if (std::uint64_t(width) * std::uint64_t(height) > limits.maxPixels || width >= (1 << 24) || height >= (1 << 24))
    throw InputError(name + ": the environment map has " + std::to_string(width) + "×" + std::to_string(height) +
                     " pixels, more than the limit of " + withThousands(limits.maxPixels) + " (raise it with --max-pixels)");
  HdrSize size{int(width), int(height)};

  // ---- Pixels: walked as stb_image decodes them, without storing any ----
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (width < 8 || width >= 32768) {  // such widths are stored flat, 4 bytes a pixel
    in.skip(4 * pixels);
    return size;
  }
  for (long y = 0; y < height; ++y) {
    const unsigned c1 = in.byte(), c2 = in.byte(), hi = in.byte();
    if (c1 != 2 || c2 != 2 || (hi & 0x80)) {
      // An old-style flat file: this was its first pixel, and the rest follow, 4 bytes each.
      if (y != 0) in.fail("row " + std::to_string(y) + " is not run-length encoded as the rows before it");
      in.skip(4 * pixels - 3);
      return size;
    }
    if (long((hi << 8) | in.byte()) != width) in.fail("row " + std::to_string(y) + " does not hold the width's pixels");
    for (int channel = 0; channel < 4; ++channel)
      for (long x = 0; x < width;) {
        unsigned count = in.byte();
        const bool run = count > 128;
        if (run) count -= 128;
        if (count == 0) in.fail("row " + std::to_string(y) + " has a run of length 0");
        if (long(count) > width - x) in.fail("row " + std::to_string(y) + " runs past the width");
        in.skip(run ? 1 : count);
        x += long(count);
      }
  }
  return size;
}

EnvironmentMap::EnvironmentMap(int width, int height, const std::vector<Vec3>& texels) : width_(width), height_(height) {
  std::shared_ptr<float> rgb(new float[3 * texels.size()], std::default_delete<float[]>());
  for (std::size_t i = 0; i < texels.size(); ++i)
    for (int c = 0; c < 3; ++c) rgb.get()[3 * i + std::size_t(c)] = float(texels[i][c]);
  rgb_ = std::move(rgb);
}

EnvironmentMap EnvironmentMap::decode(const std::string& bytes, const std::string& name, const Limits& limits) {
  if (isOpenExr(bytes)) {
    HdrSize exrSize;
    std::shared_ptr<const float> rgb = decodeOpenExr(bytes, name, limits, exrSize);
    return EnvironmentMap(exrSize.width, exrSize.height, std::move(rgb));
  }
  const HdrSize size = checkRadianceHdr(bytes, name, limits);
  int w = 0, h = 0, channels = 0;
  float* data = stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &channels, 3);
  if (!data) throw InputError(name + ": cannot decode the environment map: " + stbReason());
  std::shared_ptr<const float> rgb(data, stbi_image_free);
  if (w != size.width || h != size.height) throw InputError(name + ": cannot decode the environment map: its size changed");
  // Radiance stays finite and non-negative whatever the file says (in place: the map is big).
  for (std::size_t i = 0, n = 3 * std::size_t(w) * std::size_t(h); i < n; ++i)
    data[i] = std::isfinite(data[i]) ? std::max(0.0f, data[i]) : 0.0f;
  return EnvironmentMap(w, h, std::move(rgb));
}

namespace {

// A Radiance file is at most 4 bytes a pixel plus its header.
// A map's file is at most its pixels' bytes: RGBE's four, or an uncompressed OpenEXR's 32-bit RGBA
// with its line offsets.
std::uint64_t largestHdrFile(const Limits& limits) { return 24 * limits.maxPixels + (1 << 16); }

}  // namespace

EnvironmentMap EnvironmentMap::load(const std::filesystem::path& path, const Limits& limits) {
  return decode(readInputFile(path, largestHdrFile(limits), {"environment map", "--max-pixels"}), path.string(), limits);
}

Vec3 EnvironmentMap::radiance(const Vec3& d) const {
  constexpr Real kPi = Real(3.14159265358979323846);
  const Real u = Real(0.5) + std::atan2(d.x, -d.z) / (2 * kPi);
  const Real v = std::acos(std::clamp(d.y, Real(-1), Real(1))) / kPi;
  // Texel centres at (i + 0.5, j + 0.5); longitude wraps, latitude clamps.
  const Real x = u * Real(width_) - Real(0.5), y = v * Real(height_) - Real(0.5);
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const Real fx = x - Real(x0), fy = y - Real(y0);
  const auto at = [&](int i, int j) { return texel(((i % width_) + width_) % width_, std::clamp(j, 0, height_ - 1)); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

std::shared_ptr<const EnvironmentMapFile> EnvironmentMapFile::open(const std::filesystem::path& path, const Limits& limits) {
  auto file = std::make_shared<EnvironmentMapFile>();
  file->path_ = path;
  file->bytes_ = readInputFile(path, largestHdrFile(limits), {"environment map", "--max-pixels"});
  file->limits_ = limits;
  file->size_ = isOpenExr(file->bytes_) ? checkOpenExr(file->bytes_, path.string(), limits)
                                        : checkRadianceHdr(file->bytes_, path.string(), limits);
  return file;
}

std::shared_ptr<const EnvironmentMapFile> EnvironmentMapFile::of(std::shared_ptr<const EnvironmentMap> map) {
  auto file = std::make_shared<EnvironmentMapFile>();
  file->size_ = {map->width(), map->height()};
  file->map_ = std::move(map);
  return file;
}

const EnvironmentMap& EnvironmentMapFile::map() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (map_) return *map_;
  // The maps decoded last, by their bytes: a sheet's panels, a batch's scenes, a turntable's frames
  // read the same file again, and decode it once. Two are kept, so that memory follows the maps in
  // use rather than every map a batch has met.
  struct Decoded {
    std::string bytes;
    std::shared_ptr<const EnvironmentMap> map;
  };
  static std::mutex cacheMutex;
  static std::deque<Decoded> cache;
  constexpr std::size_t kKept = 2;
  {
    const std::lock_guard<std::mutex> cacheLock(cacheMutex);
    for (const Decoded& d : cache)
      if (d.bytes == bytes_) return *(map_ = d.map);
  }
  auto decoded = std::make_shared<const EnvironmentMap>(EnvironmentMap::decode(bytes_, path_.string(), limits_));
  const std::lock_guard<std::mutex> cacheLock(cacheMutex);
  cache.push_front({bytes_, decoded});
  if (cache.size() > kKept) cache.pop_back();
  return *(map_ = std::move(decoded));
}

}  // namespace illum
