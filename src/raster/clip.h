// Clip stage: homogeneous clipping (Sutherland–Hodgman) of one triangle against the near and far
// planes, and against an x/y guard band wide enough that everything inside it fits the
// rasterizer's fixed-point range. Triangles that merely cross the screen's edges are not cut:
// the rasterizer's scissor to the viewport handles them, so shared edges stay exact.
#pragma once

#include "raster/vertex.h"

#include <array>
#include <vector>

namespace illum {

// The guard band in pixels beyond each edge of the viewport.
constexpr int kGuardBandPixels = 8192;

enum class ClipResult { Outside, Inside, Clipped };

// Clips `tri` and appends the resulting convex polygon (0 or 3..9 vertices) to `polygon`.
ClipResult clipTriangle(const std::array<ShadedVertex, 3>& tri, int width, int height,
                        std::vector<ShadedVertex>& polygon);

}  // namespace illum
