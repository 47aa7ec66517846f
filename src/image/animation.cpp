#include <illum/animation.h>
#include <illum/error.h>

#include <gif_lib.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <cstring>
#include <memory>

namespace illum {
namespace {

int appendBytes(GifFileType* gif, const GifByteType* bytes, int count) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(gif->UserData);
  out->insert(out->end(), bytes, bytes + count);
  return count;
}

[[noreturn]] void gifFailed(int code) {
  throw Error(std::string("cannot encode the GIF: ") + (GifErrorString(code) ? GifErrorString(code) : "giflib failed"));
}

}  // namespace

std::vector<std::uint8_t> encodeGif(const std::vector<Image>& frames, int delayMs) {
  if (frames.empty()) throw Error("cannot encode a GIF of no frames");
  const int w = frames[0].width, h = frames[0].height;
  std::vector<std::uint8_t> out;
  int error = 0;
  GifFileType* gif = EGifOpen(&out, appendBytes, &error);
  if (!gif) gifFailed(error);
  const auto fail = [&](int code) {
    int ignored = 0;
    EGifCloseFile(gif, &ignored);
    gifFailed(code);
  };
  EGifSetGifVersion(gif, true);
  if (EGifPutScreenDesc(gif, w, h, 8, 0, nullptr) == GIF_ERROR) fail(gif->Error);
  // Loop forever (the NETSCAPE2.0 application extension).
  static const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  static const GifByteType loop[] = {1, 0, 0};
  if (EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, sizeof netscape, netscape) == GIF_ERROR ||
      EGifPutExtensionBlock(gif, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(gif) == GIF_ERROR)
    fail(gif->Error);
  const std::size_t n = std::size_t(w) * std::size_t(h);
  std::vector<GifByteType> r(n), g(n), b(n), index(n);
  for (const Image& frame : frames) {
    bool transparent = false;
    for (std::size_t i = 0; i < n; ++i) {
      r[i] = frame.rgba[4 * i], g[i] = frame.rgba[4 * i + 1], b[i] = frame.rgba[4 * i + 2];
      transparent = transparent || frame.rgba[4 * i + 3] < 128;
    }
    // 255 colours from the picture, the 256th kept for transparency.
    GifColorType palette[256] = {};
    int size = transparent ? 255 : 256;
    if (GifQuantizeBuffer(unsigned(w), unsigned(h), &size, r.data(), g.data(), b.data(), index.data(), palette) == GIF_ERROR)
      throw Error("cannot encode the GIF: quantizing a frame failed");
    if (transparent)
      for (std::size_t i = 0; i < n; ++i)
        if (frame.rgba[4 * i + 3] < 128) index[i] = 255;
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSE_BACKGROUND;
    gcb.DelayTime = std::max(1, delayMs / 10);  // hundredths of a second
    gcb.TransparentColor = transparent ? 255 : NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&gcb, extension);
    if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, int(length), extension) == GIF_ERROR) fail(gif->Error);
    const std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(GifMakeMapObject(256, palette), GifFreeMapObject);
    if (!map || EGifPutImageDesc(gif, 0, 0, w, h, false, map.get()) == GIF_ERROR) fail(gif->Error);
    for (int y = 0; y < h; ++y)
      if (EGifPutLine(gif, &index[std::size_t(y) * std::size_t(w)], w) == GIF_ERROR) fail(gif->Error);
  }
  if (EGifCloseFile(gif, &error) == GIF_ERROR) gifFailed(error);
  return out;
}

std::vector<std::uint8_t> encodeWebp(const std::vector<Image>& frames, int delayMs) {
  if (frames.empty()) throw Error("cannot encode a WebP of no frames");
  const int w = frames[0].width, h = frames[0].height;
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options)) throw Error("cannot encode the WebP: libwebp version mismatch");
  options.anim_params.loop_count = 0;  // forever
  const std::unique_ptr<WebPAnimEncoder, void (*)(WebPAnimEncoder*)> encoder(WebPAnimEncoderNew(w, h, &options),
                                                                              WebPAnimEncoderDelete);
  WebPConfig config;
  if (!encoder || !WebPConfigInit(&config)) throw Error("cannot encode the WebP: out of memory");
  config.lossless = 1;
  config.quality = 50;  // lossless effort: fast, still small
  config.method = 1;
  int timestamp = 0;
  for (const Image& frame : frames) {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw Error("cannot encode the WebP: libwebp version mismatch");
    picture.use_argb = 1;
    picture.width = w, picture.height = h;
    if (!WebPPictureImportRGBA(&picture, frame.rgba.data(), w * 4)) throw Error("cannot encode the WebP: out of memory");
    const bool added = WebPAnimEncoderAdd(encoder.get(), &picture, timestamp, &config);
    WebPPictureFree(&picture);
    if (!added) throw Error(std::string("cannot encode the WebP: ") + WebPAnimEncoderGetError(encoder.get()));
    timestamp += delayMs;
  }
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAdd(encoder.get(), nullptr, timestamp, nullptr) || !WebPAnimEncoderAssemble(encoder.get(), &data))
    throw Error(std::string("cannot encode the WebP: ") + WebPAnimEncoderGetError(encoder.get()));
  std::vector<std::uint8_t> out(data.bytes, data.bytes + data.size);
  WebPDataClear(&data);
  return out;
}

}  // namespace illum
