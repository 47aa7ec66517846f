// picture_texture.h; the bytes' reordering compiled once per SIMD target (Highway's
// foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "picture_texture.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace illum::view::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// RGBA8 bytes to memory order B, G, R, A (R and B trade places): a byte shuffle per vector (x86's
// pshufb), which at 1280×720 takes a third of the time the compiler's SSE2 shifts and masks took.
void SwapRedAndBlue(const std::uint8_t* from, std::uint8_t* to, int pixels) {
  const hn::ScalableTag<std::uint8_t> d;
  const int lanes = int(hn::Lanes(d)), bytes = pixels * 4;
  // Byte i takes byte (i & ~3) + {2, 1, 0, 3}[i & 3] of its 16-byte block (the shuffle's reach).
  HWY_ALIGN std::uint8_t order[hn::MaxLanes(d)];
  constexpr std::uint8_t kSwapped[4] = {2, 1, 0, 3};
  for (int i = 0; i < lanes; ++i) order[i] = std::uint8_t((i & 12) + kSwapped[i & 3]);
  const auto indices = hn::Load(d, order);
  int i = 0;
  for (; i + lanes <= bytes; i += lanes) hn::StoreU(hn::TableLookupBytes(hn::LoadU(d, from + i), indices), d, to + i);
  for (; i < bytes; i += 4) to[i] = from[i + 2], to[i + 1] = from[i + 1], to[i + 2] = from[i], to[i + 3] = from[i + 3];
}

}  // namespace illum::view::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "picture_texture.h"

#include <cstring>
#include <string>

namespace illum::view {
HWY_EXPORT(SwapRedAndBlue);

namespace {

// The GL's name, when `renderer` draws through one (its context is current after creation).
std::string glRendererName(SDL_Renderer* renderer) {
  SDL_RendererInfo info{};
  if (SDL_GetRendererInfo(renderer, &info) != 0 || !info.name) return "";
  const std::string driver = info.name;
  if (driver.rfind("opengl", 0) != 0) return "";
  using GetString = const unsigned char* (*)(unsigned int);
  const auto getString = reinterpret_cast<GetString>(SDL_GL_GetProcAddress("glGetString"));
  constexpr unsigned int kGlRenderer = 0x1F01;
  const unsigned char* name = getString ? getString(kGlRenderer) : nullptr;
  return name ? reinterpret_cast<const char*>(name) : "";
}

bool drawnOnTheCpu(const std::string& glName) {
  return glName.find("llvmpipe") != std::string::npos || glName.find("softpipe") != std::string::npos;
}

}  // namespace

SDL_Renderer* createPresentingRenderer(SDL_Window* window) {
  const bool chosen = SDL_GetHint(SDL_HINT_RENDER_DRIVER) != nullptr;
  if (SDL_Renderer* accelerated = SDL_CreateRenderer(window, -1, SDL_RENDERER_ACCELERATED)) {
    if (chosen || !drawnOnTheCpu(glRendererName(accelerated))) return accelerated;
    SDL_DestroyRenderer(accelerated);
  }
  // The window's surface itself, not one that SDL would in turn draw through the GL.
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  return SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE);
}

PictureTexture::PictureTexture(SDL_Window* window, SDL_Renderer* renderer) : renderer_(renderer) {
  SDL_RendererInfo info{};
  SDL_GetRendererInfo(renderer, &info);
  const bool software = (info.flags & SDL_RENDERER_SOFTWARE) != 0;
  const Uint32 surface = SDL_GetWindowPixelFormat(window);
  // RGBA8 bytes are SDL's ABGR8888 on a little-endian machine: the GL takes them as they are; the
  // software renderer's window surface is usually XRGB (RGB888) or ARGB8888, R and B swapped.
  format_ = software && (surface == SDL_PIXELFORMAT_RGB888 || surface == SDL_PIXELFORMAT_ARGB8888)
                ? surface
                : Uint32(SDL_PIXELFORMAT_ABGR8888);
}

PictureTexture::~PictureTexture() {
  if (texture_) SDL_DestroyTexture(texture_);
}

void PictureTexture::update(const Image& image) {
  if (!texture_ || width_ != image.width || height_ != image.height) {
    if (texture_) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, format_, SDL_TEXTUREACCESS_STREAMING, image.width, image.height);
    if (!texture_) return;
    SDL_SetTextureBlendMode(texture_, SDL_BLENDMODE_NONE);
    width_ = image.width, height_ = image.height;
  }
  void* pixels = nullptr;
  int pitch = 0;
  if (SDL_LockTexture(texture_, nullptr, &pixels, &pitch) != 0) return;
  const std::size_t row = std::size_t(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* from = image.rgba.data() + std::size_t(y) * row;
    auto* to = static_cast<std::uint8_t*>(pixels) + std::size_t(y) * std::size_t(pitch);
    if (format_ == SDL_PIXELFORMAT_ABGR8888) {
      std::memcpy(to, from, row);
      continue;
    }
    HWY_DYNAMIC_DISPATCH(SwapRedAndBlue)(from, to, image.width);
  }
  SDL_UnlockTexture(texture_);
}

}  // namespace illum::view
#endif  // HWY_ONCE
