// `illum render --debug-pixel x,y`: what was computed at one pixel, step by step, and the bytes
// that ended up in the file there.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace illum::cli {

// What happens to a pixel after its fragments: the multisample resolve (with blending), the display
// encoding, and what is drawn over it; found by drawing the scene again without its labels and
// display encoding (the rasterizer's 8-bit framebuffer, as GL's), and each label alone.
struct PixelChain {
  int samples = 1;
  std::array<std::uint8_t, 4> resolved{};   // the framebuffer's bytes, before the display encoding
  std::array<std::uint8_t, 4> displayed{};  // after the tone map and the encoding
  std::vector<std::string> overlays;        // what is drawn over the pixel
};
PixelChain tracePixelChain(const Scene& scene, int x, int y);

// `image` is the picture as written (after blending and labels); the report goes to `out`. With
// `chain`, the steps from the fragment to the file's bytes too.
void printPixelReport(const Scene& scene, const PixelProbe& probe, const Image& image, std::FILE* out = stdout,
                      const PixelChain* chain = nullptr);

}  // namespace illum::cli
