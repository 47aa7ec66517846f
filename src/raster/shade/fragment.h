// Fragment stage: the colour of one covered pixel for each shading frequency.
//   flat:    the colour lit at the triangle's provoking (last) vertex;
//   gouraud: the vertex colours, interpolated perspective-correctly;
//   phong:   normal and eye position interpolated perspective-correctly, lit per pixel.
#pragma once

#include "raster/setup/draw_record.h"
#include "raster/frame_context.h"
#include "raster/setup/setup.h"
#include "shading/material_at.h"

#include <illum/texture.h>

namespace illum {

// The screen-space barycentrics of pixel (x, y)'s centre, as the rasterizer computes them (the
// edge functions evaluated exactly, then scaled). A multisample pass moved the triangle by
// −sample: the centre is at centre − sample there, so its shading is the same in every pass.
inline std::array<Real, 3> centreBarycentrics(const TriangleSetup& t, int x, int y, SubpixelOffset sample) {
  const std::int64_t fx = std::int64_t(x) * kSubpixelOne + kSubpixelOne / 2 - sample.x;
  const std::int64_t fy = std::int64_t(y) * kSubpixelOne + kSubpixelOne / 2 - sample.y;
  return {Real(t.edge[0].at(fx, fy)) * t.invArea, Real(t.edge[1].at(fx, fy)) * t.invArea,
          Real(t.edge[2].at(fx, fy)) * t.invArea};
}

// Screen-space barycentrics → perspective-correct weights (λi/wi normalized).
inline std::array<Real, 3> perspectiveWeights(const TriangleSetup& t, Real l0, Real l1, Real l2) {
  const Real q0 = l0 * t.invW[0], q1 = l1 * t.invW[1], q2 = l2 * t.invW[2];
  const Real inv = Real(1) / (q0 + q1 + q2);
  return {q0 * inv, q1 * inv, q2 * inv};
}

// What Phong shading lights at a pixel: the interpolated eye position, the interpolated normal
// renormalized (−N for a back face under two-sided lighting), and with `vertexColors` the
// interpolated vertex colour, which stands for the ambient and diffuse material.
struct PhongSurface {
  Vec3 position, normal;
  Color4 color;
};
PhongSurface phongSurface(const FrameContext& frame, bool vertexColors, const DrawRecord& r, const AttributeLayout& l,
                          const std::array<Real, 3>& w);

// The per-pixel lighting of Phong shading, one pixel at a time (the binned pipeline lights its
// pixels in batches, shade_tile.cpp, with the same equation), of an object without maps. With
// `texel`, the object's texel at the pixel: it tints the base colour before lighting where
// texelIsBaseColor says so (the caller multiplies the lit colour by it otherwise). `seed` is the
// pixel's (OcclusionQuery::pixelSeed), for the frame's ambient occlusion.
Color4 shadePhongFragment(const FrameContext& frame, const Object& object, const DrawRecord& r,
                          const AttributeLayout& l, const std::array<Real, 3>& w, const Vec4* texel,
                          std::uint64_t seed);

// Where a pixel falls on the textures: its perspective-correct uv, and how much uv changes one
// pixel to the right and one up (the uv evaluated there), which sets each texture's footprint.
struct TexturePoint {
  Vec2 uv, dx, dy;
};
TexturePoint texturePoint(const DrawRecord& r, const AttributeLayout& l, Real l0, Real l1, Real l2);
// A texture's texel at the point, trilinearly filtered for its footprint there.
Vec4 sampleAt(const Texture& texture, const TexturePoint& p);

// The texel that modulates the pixel (the diffuse or base colour texture).
inline Vec4 sampleDiffuseTexture(const Texture& texture, const DrawRecord& r, const AttributeLayout& l, Real l0,
                                 Real l1, Real l2) {
  return sampleAt(texture, texturePoint(r, l, l0, l1, l2));
}

// A pixel of an object whose maps are drawn (mapsDrawn), as Phong shading lights it: the
// interpolated surface with the normal map's normal, and the material at the point (vertex
// colours, the texel and the maps' texels, materialAt). Lit one pixel at a time by the one-lane
// equation, which gives the same bits as the SIMD batches.
struct MappedSurface {
  Vec3 position, normal;
  PointMaterial point;
};
MappedSurface mappedSurface(const FrameContext& frame, const Object& object, const DrawRecord& r,
                            const AttributeLayout& l, Real l0, Real l1, Real l2);
Color4 shadeMappedFragment(const FrameContext& frame, const MappedSurface& surface, std::uint64_t seed);

// Gouraud: the vertex colours (lit for the side shown), interpolated.
inline Color4 gouraudColor(const DrawRecord& r, const AttributeLayout& l, const std::array<Real, 3>& w) {
  return w[0] * VertexValues{r.vertex(0, l), l}.lit() + w[1] * VertexValues{r.vertex(1, l), l}.lit() +
         w[2] * VertexValues{r.vertex(2, l), l}.lit();
}

}  // namespace illum
