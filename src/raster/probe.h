// --debug-pixel: the fragments at one watched pixel, worked out apart from the frame. The frame is
// drawn by its own routes, unchanged by the watching; the probe then draws every triangle of the
// scene, in the drawing order, over that one pixel by the one-pixel formulas (draw.h) that every
// route's colours equal bit for bit, and keeps the last fragment written there (multisampled: the
// first sample's, as a pass at that sample draws it).
#pragma once

#include <illum/render.h>

#include "raster/frame_context.h"

#include <vector>

namespace illum {

void probePixel(const Scene& scene, const FrameContext& frame, PixelProbe& probe);

}  // namespace illum
