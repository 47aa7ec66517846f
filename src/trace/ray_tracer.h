// The ray tracers' frame: the scene's BVH, primary rays in 4×4 packets over 16×16-pixel tiles in
// parallel (oneTBB), each pixel's samples averaged. Deterministic: a pixel's rays and their order
// depend on the pixel alone, so every thread count gives the same bytes.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <functional>

namespace illum {

// `probe`, if given, is filled from the centre ray of its pixel (the first sample).
// `linear`, if given, receives each pixel's mean before its 8-bit conversion.
// `progress`, if set, hears the fraction of tiles done (from the worker threads). The picture is
// finished (labels) by the caller, render/.
void traceScene(const Scene& scene, Image& image, RenderStats& stats, PixelProbe* probe = nullptr,
                FloatImage* linear = nullptr, const std::function<void(double)>& progress = {});

}  // namespace illum
