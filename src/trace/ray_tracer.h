// The ray tracers' frame: the scene's BVH, primary rays in 4×4 packets over 16×16-pixel tiles in
// parallel (oneTBB), each pixel's samples averaged. Deterministic: a pixel's rays and their order
// depend on the pixel alone, so every thread count gives the same bytes.
#pragma once

#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include <atomic>
#include <functional>

namespace illum {

// `probe`, if given, is filled from the centre ray of its pixel (the first sample).
// `linear`, if given, receives each pixel's mean before its 8-bit conversion.
// `progress`, if set, hears the fraction of tiles done (from the worker threads). The picture is
// finished (labels) by the caller, render/.
// `cancel`, if set, stops the frame between tiles (Renderer::setCancel).
void traceScene(const Scene& scene, Image& image, RenderStats& stats, PixelProbe* probe = nullptr,
                FloatImage* linear = nullptr, const std::function<void(double)>& progress = {},
                const std::atomic<bool>* cancel = nullptr);

}  // namespace illum
