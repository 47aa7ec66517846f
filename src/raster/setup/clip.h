// Clip stage: homogeneous clipping (Sutherland–Hodgman) of one triangle against the near and far
// planes, and against an x/y guard band wide enough that everything inside it fits the
// rasterizer's fixed-point range. Triangles that merely cross the screen's edges are not cut:
// the rasterizer's scissor to the viewport handles them, so shared edges stay exact.
#pragma once

#include "raster/setup/vertex.h"

#include <array>

namespace illum {

// The guard band in pixels beyond each edge of the viewport.
constexpr int kGuardBandPixels = 8192;

enum class ClipResult { Outside, Inside, Clipped };

// Which clip planes a clip-space position is beyond (bit p for plane p: near, far, −x, +x, −y,
// +y of the guard band), and kNotFinite for a position no plane can judge. 0 is inside.
constexpr unsigned kNotFinite = 1u << 6;
// The guard band's half extents in NDC units: x within ±gx·w, y within ±gy·w.
Vec2 guardBandScale(int width, int height);
unsigned clipOutcode(const Vec4& clip, int width, int height);

// Trivial accept and reject: Outside (wholly beyond one plane, or not finite), Inside (needs no
// cut), or Clipped (clipTriangle must cut it). `outsidePlanes` gets the planes any vertex is beyond.
ClipResult classifyTriangle(const ShadedVertex& a, const ShadedVertex& b, const ShadedVertex& c, int width, int height,
                            unsigned* outsidePlanes = nullptr);

// A convex polygon of at most 9 vertices (a triangle cut by 6 planes), held without the heap.
struct ClippedPolygon {
  std::array<ShadedVertex, 9> vertex;
  std::size_t size = 0;
};

// Clips `tri` into `polygon` (0 or 3..9 vertices).
ClipResult clipTriangle(const std::array<ShadedVertex, 3>& tri, int width, int height, ClippedPolygon& polygon);

}  // namespace illum
