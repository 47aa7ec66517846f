#include <illum/animation.h>
#include <illum/error.h>

#include <gif_lib.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <array>
#include <optional>
#include <cstring>
#include <memory>
#include <utility>

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

class GifEncoder final : public AnimationEncoder {
 public:
  GifEncoder(int width, int height, int delayMs, std::optional<std::array<std::uint8_t, 3>> exact)
      : w_(width), h_(height), delayMs_(delayMs), exact_(exact) {
    int error = 0;
    gif_ = EGifOpen(&out_, appendBytes, &error);
    if (!gif_) gifFailed(error);
    EGifSetGifVersion(gif_, true);
    if (EGifPutScreenDesc(gif_, w_, h_, 8, 0, nullptr) == GIF_ERROR) fail(gif_->Error);
    // Loop forever (the NETSCAPE2.0 application extension).
    static const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    static const GifByteType loop[] = {1, 0, 0};
    if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof netscape, netscape) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(gif_) == GIF_ERROR)
      fail(gif_->Error);
    const std::size_t n = std::size_t(w_) * std::size_t(h_);
    r_.resize(n), g_.resize(n), b_.resize(n), index_.resize(n);
  }
  ~GifEncoder() override { close(); }

  void add(const Image& frame) override {
    const std::size_t n = r_.size();
    bool transparent = false;
    for (std::size_t i = 0; i < n; ++i) {
      r_[i] = frame.rgba[4 * i], g_[i] = frame.rgba[4 * i + 1], b_[i] = frame.rgba[4 * i + 2];
      transparent = transparent || frame.rgba[4 * i + 3] < 128;
    }
    // The colours quantized from the picture; the last entry kept for transparency, and the one
    // before it, with an exact colour (the background's), for the pixels of exactly that colour.
    GifColorType palette[256] = {};
    const int transparentIndex = 255, exactIndex = transparent ? 254 : 255;
    int size = 256 - int(transparent) - int(exact_.has_value());
    if (GifQuantizeBuffer(unsigned(w_), unsigned(h_), &size, r_.data(), g_.data(), b_.data(), index_.data(), palette) ==
        GIF_ERROR)
      throw Error("cannot encode the GIF: quantizing a frame failed");
    if (exact_) {
      const auto& [r, g, b] = *exact_;
      palette[exactIndex] = {r, g, b};
      for (std::size_t i = 0; i < n; ++i)
        if (r_[i] == r && g_[i] == g && b_[i] == b) index_[i] = GifByteType(exactIndex);
    }
    if (transparent)
      for (std::size_t i = 0; i < n; ++i)
        if (frame.rgba[4 * i + 3] < 128) index_[i] = GifByteType(transparentIndex);
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSE_BACKGROUND;
    gcb.DelayTime = std::max(1, delayMs_ / 10);  // hundredths of a second
    gcb.TransparentColor = transparent ? transparentIndex : NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&gcb, extension);
    if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, int(length), extension) == GIF_ERROR) fail(gif_->Error);
    const std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> map(GifMakeMapObject(256, palette), GifFreeMapObject);
    if (!map || EGifPutImageDesc(gif_, 0, 0, w_, h_, false, map.get()) == GIF_ERROR) fail(gif_->Error);
    for (int y = 0; y < h_; ++y)
      if (EGifPutLine(gif_, &index_[std::size_t(y) * std::size_t(w_)], w_) == GIF_ERROR) fail(gif_->Error);
    ++frames_;
  }

  std::vector<std::uint8_t> finish() override {
    if (frames_ == 0) throw Error("cannot encode a GIF of no frames");
    int error = 0;
    GifFileType* gif = std::exchange(gif_, nullptr);
    if (EGifCloseFile(gif, &error) == GIF_ERROR) gifFailed(error);
    return std::move(out_);
  }

 private:
  void close() {
    int ignored = 0;
    if (gif_) EGifCloseFile(std::exchange(gif_, nullptr), &ignored);
  }
  [[noreturn]] void fail(int code) {
    close();
    gifFailed(code);
  }

  int w_, h_, delayMs_, frames_ = 0;
  std::optional<std::array<std::uint8_t, 3>> exact_;
  GifFileType* gif_ = nullptr;
  std::vector<std::uint8_t> out_;
  std::vector<GifByteType> r_, g_, b_, index_;
};

class WebpEncoder final : public AnimationEncoder {
 public:
  WebpEncoder(int width, int height, int delayMs) : w_(width), h_(height), delayMs_(delayMs) {
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options)) throw Error("cannot encode the WebP: libwebp version mismatch");
    options.anim_params.loop_count = 0;  // forever
    encoder_.reset(WebPAnimEncoderNew(w_, h_, &options));
    if (!encoder_ || !WebPConfigInit(&config_)) throw Error("cannot encode the WebP: out of memory");
    config_.lossless = 1;
    config_.quality = 50;  // lossless effort: fast, still small
    config_.method = 1;
  }

  void add(const Image& frame) override {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw Error("cannot encode the WebP: libwebp version mismatch");
    picture.use_argb = 1;
    picture.width = w_, picture.height = h_;
    if (!WebPPictureImportRGBA(&picture, frame.rgba.data(), w_ * 4)) throw Error("cannot encode the WebP: out of memory");
    const bool added = WebPAnimEncoderAdd(encoder_.get(), &picture, timestamp_, &config_);
    WebPPictureFree(&picture);
    if (!added) throw Error(std::string("cannot encode the WebP: ") + WebPAnimEncoderGetError(encoder_.get()));
    timestamp_ += delayMs_;
    ++frames_;
  }

  std::vector<std::uint8_t> finish() override {
    if (frames_ == 0) throw Error("cannot encode a WebP of no frames");
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAdd(encoder_.get(), nullptr, timestamp_, nullptr) || !WebPAnimEncoderAssemble(encoder_.get(), &data))
      throw Error(std::string("cannot encode the WebP: ") + WebPAnimEncoderGetError(encoder_.get()));
    std::vector<std::uint8_t> out(data.bytes, data.bytes + data.size);
    WebPDataClear(&data);
    return out;
  }

 private:
  int w_, h_, delayMs_, frames_ = 0, timestamp_ = 0;
  std::unique_ptr<WebPAnimEncoder, void (*)(WebPAnimEncoder*)> encoder_{nullptr, WebPAnimEncoderDelete};
  WebPConfig config_{};
};

}  // namespace

std::unique_ptr<AnimationEncoder> makeGifEncoder(int width, int height, int delayMs,
                                                 std::optional<std::array<std::uint8_t, 3>> exact) {
  return std::make_unique<GifEncoder>(width, height, delayMs, exact);
}

std::unique_ptr<AnimationEncoder> makeWebpEncoder(int width, int height, int delayMs) {
  return std::make_unique<WebpEncoder>(width, height, delayMs);
}

}  // namespace illum
