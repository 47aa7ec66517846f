// `illum render --debug-pixel x,y`: what was computed at one pixel, step by step, and the bytes
// that ended up in the file there.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <cstdio>

namespace illum::cli {

// `image` is the picture as written (after blending and labels); the report goes to `out`.
void printPixelReport(const Scene& scene, const PixelProbe& probe, const Image& image, std::FILE* out = stdout);

}  // namespace illum::cli
