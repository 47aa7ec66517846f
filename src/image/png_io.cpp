#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>

#include <libdeflate.h>
#include <stb_image.h>

#include <cstring>
#include <memory>

namespace illum {
namespace {

struct Compressor {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

// One PNG chunk: length, type, data, and the CRC-32 of type and data (PNG §5.3).
void putChunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, std::size_t size) {
  putBigEndian(out, std::uint32_t(size));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  putBigEndian(out, std::uint32_t(libdeflate_crc32(0, out.data() + start, size + 4)));
}

}  // namespace

// An RGBA8 PNG whose rows all use the "sub" filter (each byte minus the same channel of the pixel
// to its left: rendered pictures are mostly smooth runs, which this turns into runs of zeros),
// compressed by libdeflate at its fastest level: several times faster than stb_image_write or
// zlib, a few percent larger than zlib's default. The PNG framing is the format's own (signature,
// IHDR, one IDAT, IEND); the compression is libdeflate's. The same bytes on every run.
namespace {

// Sub-filtered rows (`bytesPerPixel` apart) compressed into a PNG of the given bit depth, RGBA.
std::vector<std::uint8_t> encodeRows(int width, int height, const std::uint8_t* pixels, std::size_t bytesPerPixel,
                                     std::uint8_t bitDepth) {
  const std::size_t stride = std::size_t(width) * bytesPerPixel;
  std::vector<std::uint8_t> filtered((stride + 1) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    std::uint8_t* out = &filtered[std::size_t(y) * (stride + 1)];
    const std::uint8_t* row = pixels + std::size_t(y) * stride;
    out[0] = 1;  // filter type 1: sub
    std::memcpy(out + 1, row, std::min(bytesPerPixel, stride));
    for (std::size_t i = bytesPerPixel; i < stride; ++i) out[1 + i] = std::uint8_t(row[i] - row[i - bytesPerPixel]);
  }
  const std::unique_ptr<libdeflate_compressor, Compressor> compressor(libdeflate_alloc_compressor(1));
  if (!compressor) throw Error("cannot encode a PNG: out of memory");
  // Room for the worst case, left uninitialised: only the bytes written are ever touched (a
  // 1080p picture's bound is 8 MiB, its stream mostly well under one).
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor.get(), filtered.size());
  const std::unique_ptr<std::uint8_t[]> idat(new std::uint8_t[bound]);
  const std::size_t size = libdeflate_zlib_compress(compressor.get(), filtered.data(), filtered.size(), idat.get(), bound);
  if (size == 0) throw Error("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " PNG");

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  png.reserve(size + 64);
  std::vector<std::uint8_t> header;
  putBigEndian(header, std::uint32_t(width));
  putBigEndian(header, std::uint32_t(height));
  header.insert(header.end(), {bitDepth, 6, 0, 0, 0});  // RGBA, deflate, adaptive filtering, no interlace
  putChunk(png, "IHDR", header.data(), header.size());
  putChunk(png, "IDAT", idat.get(), size);
  putChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& image) {
  return encodeRows(image.width, image.height, image.rgba.data(), 4, 8);
}

std::vector<std::uint8_t> encodePng16(int width, int height, const std::vector<std::uint16_t>& rgba) {
  std::vector<std::uint8_t> bytes(rgba.size() * 2);
  for (std::size_t i = 0; i < rgba.size(); ++i) bytes[2 * i] = std::uint8_t(rgba[i] >> 8), bytes[2 * i + 1] = std::uint8_t(rgba[i]);
  return encodeRows(width, height, bytes.data(), 8, 16);
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
