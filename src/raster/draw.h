// What the two drivers of the pipeline share (pipeline.cpp, binned and parallel; reference/, in
// submission order on one thread): turning an object's triangles into self-contained draw records
// (clip → setup), and drawing one record's fragments (rasterize → fragment → framebuffer).
#pragma once

#include <illum/render.h>

#include "raster/frame_context.h"
#include "raster/framebuffer.h"
#include "raster/rasterize.h"
#include "raster/setup.h"
#include "raster/vertex.h"

#include <cstdint>
#include <vector>

namespace illum {

// Flat shading's colours and what they were lit with: GL's provoking vertex is the triangle's last.
struct ProvokingVertex {
  Color4 front, back;
  Vec3 eyePosition, eyeNormal;
};

// One triangle ready to draw, needing nothing but the frame and its object.
struct DrawRecord {
  TriangleSetup setup;
  ProvokingVertex flat;
  std::uint32_t object = 0;    // index into Scene::objects
  std::uint32_t triangle = 0;  // of that object's mesh
};

// What every triangle of a frame draws into.
struct DrawTarget {
  const FrameContext& frame;
  const Scene& scene;
  Framebuffer& fb;
  PixelProbe* probe;  // null unless a pixel is watched
};

// Clips and sets up triangles [first, last) of `object` (its vertices already through the vertex
// stage), appending a record for each drawn (clipped) piece in submission order. Returns how many
// were appended.
std::size_t setupTriangles(const FrameContext& frame, const Object& object, std::uint32_t objectIndex,
                           const std::vector<ShadedVertex>& vertices, std::size_t first, std::size_t last,
                           std::vector<DrawRecord>& out);

// Draws the record's pixels inside `rect`; adds the fragments that passed the depth test.
void drawRecord(const DrawTarget& target, const DrawRecord& record, const PixelRect& rect, std::size_t& fragments);

// Records the fragment at the watched pixel: where it was lit (weights w), the lit colour, the
// texel that modulated it (null without a texture) and what was written.
void recordProbe(const DrawTarget& target, const DrawRecord& record, const std::array<Real, 3>& w, const Color4& lit,
                 const Vec4* texel, const Color4& written);

// Scene order, or with blending the opaque objects first and then the translucent ones from the
// farthest to the nearest. Ties keep scene order.
std::vector<const Object*> drawingOrder(const Scene& scene, const FrameContext& frame);

// The finished picture: the framebuffer as an image, the pixels drawn counted (labels aside),
// then the scene's labels drawn over it.
Image finishFrame(const Framebuffer& fb, const Scene& scene, RenderStats& stats);

}  // namespace illum
