// `illum render --debug-pixel x,y`: every term of the lighting equation at one pixel.
#pragma once

#include <illum/render.h>
#include <illum/scene.h>

namespace illum::cli {

void printPixelReport(const Scene& scene, const PixelProbe& probe);

}  // namespace illum::cli
