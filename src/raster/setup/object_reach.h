// How far an object's triangles can reach on the screen, known before any of them is set up: the
// window rectangle of its mesh's bounding box, projected. A tile beyond the reach of every object
// still to be drawn is finished, and can be resolved and given its memory back before the frame
// ends (pipeline.cpp).
#pragma once

#include "raster/coverage/rasterize.h"
#include "raster/frame_context.h"

#include <illum/scene.h>

namespace illum {

// Pixels every triangle of `object` that covers a sample lies in: its box's eight corners in
// clip space (where w is positive throughout the box, perspective projection maps the box into
// the hull of their images, and clipping keeps what it keeps of a triangle inside that), widened
// by a margin far beyond the vertex stage's rounding; the whole frame when a corner is behind the
// eye or not finite, or the mesh has no positions. Clamped to the frame; minX >
// maxX when the box lies outside it.
PixelRect objectReach(const FrameContext& frame, const Object& object);

}  // namespace illum
