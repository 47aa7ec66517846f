// Still pictures besides PNG and OpenEXR: JPEG through libjpeg-turbo, WebP through libwebp, encoded
// in memory so that writeOutputFile can put them in place safely.
#include <illum/error.h>
#include <illum/image.h>

// jpeglib.h needs the standard types declared first.
#include <cstddef>
#include <cstdio>

#include <jpeglib.h>
#include <webp/encode.h>

#include <csetjmp>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace illum {
namespace {

// libjpeg reports errors through a callback that must not return: it jumps back here.
struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

void onJpegError(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->back, 1);
}

}  // namespace

std::vector<std::uint8_t> encodeJpeg(const Image& image, int quality) {
  if (quality < 1 || quality > 100) throw InputError("JPEG quality: expected 1 to 100, got " + std::to_string(quality));
  // The RGB rows first: nothing below may throw between setjmp and the end of the encoding.
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  std::vector<unsigned char> rgb(w * h * 3);
  for (std::size_t i = 0; i < w * h; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
  jpeg_compress_struct info{};
  JpegError error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = onJpegError;
  unsigned char* bytes = nullptr;
  unsigned long size = 0;
  if (setjmp(error.back)) {
    jpeg_destroy_compress(&info);
    std::free(bytes);
    throw Error(std::string("cannot encode the JPEG: ") + error.message);
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &bytes, &size);
  info.image_width = JDIMENSION(w);
  info.image_height = JDIMENSION(h);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  info.optimize_coding = TRUE;  // smaller files for the same pixels
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = rgb.data() + std::size_t(info.next_scanline) * w * 3;
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::vector<std::uint8_t> out(bytes, bytes + size);
  std::free(bytes);
  return out;
}

std::vector<std::uint8_t> encodeWebp(const Image& image, std::optional<int> quality) {
  if (quality && (*quality < 1 || *quality > 100))
    throw InputError("WebP quality: expected 1 to 100, got " + std::to_string(*quality));
  std::uint8_t* bytes = nullptr;
  const int stride = image.width * 4;
  const std::size_t size =
      quality ? WebPEncodeRGBA(image.rgba.data(), image.width, image.height, stride, float(*quality), &bytes)
              : WebPEncodeLosslessRGBA(image.rgba.data(), image.width, image.height, stride, &bytes);
  const std::unique_ptr<std::uint8_t, void (*)(void*)> owned(bytes, WebPFree);
  if (size == 0 || !bytes) throw Error("cannot encode the WebP (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
  return {bytes, bytes + size};
}

}  // namespace illum
