// Vertex stage: object space → eye space → clip space, normals by the inverse transpose,
// and, for flat and Gouraud shading, the lighting equation at every vertex.
#pragma once

#include "raster/frame_context.h"

#include <cstdint>
#include <span>
#include <vector>

namespace illum {

// Window coordinates: x and y in fixed point with 8 sub-pixel bits (y up), depth in [0,1], 1/w.
struct WindowPosition {
  std::int64_t x = 0, y = 0;
  Real z = 0, invW = 0;
};

constexpr unsigned kOutcodeUnknown = ~0u;

// A vertex after the vertex stage: its clip-space position and, computed once here rather than
// once per triangle that shares it, its clip outcode and window position; then what the fragment
// stage interpolates across a triangle. Laid out for the setup of dense meshes, whose vertex
// arrays are far larger than the caches: what every triangle's setup reads (window position,
// outcode) and the Gouraud colour share the first 64-byte line, so that most triangles, which
// cover no pixel centre, cost one line per vertex.
struct alignas(64) ShadedVertex {
  WindowPosition window;
  unsigned outcode = kOutcodeUnknown;  // clipOutcode(clip) (clip.h), once known
  bool hasWindow = false;              // `window` is toWindow(clip): the vertex is inside the clip volume
  Vec4 clip{0};                        // clipFromView · viewFromObject · p
  Color4 front{0};                     // lit with N (flat, Gouraud)
  Vec3 eyePosition{0};
  Vec3 eyeNormal{0};  // unit length (GL_NORMALIZE)
  Color4 back{0};     // lit with −N (two-sided lighting only)
  Vec2 uv{0};         // texture coordinates, when the mesh has them
  Color4 color{1};    // the vertex colour, when the mesh has them (GL_COLOR_MATERIAL)
};

// The object's vertices [first, last) through the vertex stage, into `out` (as many as the mesh's
// vertices); each vertex independent of the others, so ranges can run in parallel. `objectIndex`
// (in the scene) numbers the vertices' occlusion rays.
void runVertexStage(const FrameContext& frame, const Object& object, std::uint32_t objectIndex,
                    std::span<ShadedVertex> out, std::size_t first, std::size_t last);

// Linear interpolation of every attribute, as clipping needs it.
ShadedVertex lerp(const ShadedVertex& a, const ShadedVertex& b, Real t);

}  // namespace illum
