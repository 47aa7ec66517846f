#include "raster/shade/fragment.h"

#include "shading/material_maps.h"

namespace illum {

PhongSurface phongSurface(const FrameContext& frame, bool vertexColors, const DrawRecord& r, const AttributeLayout& l,
                          const std::array<Real, 3>& w) {
  const VertexValues v[3] = {{r.vertex(0, l), l}, {r.vertex(1, l), l}, {r.vertex(2, l), l}};
  PhongSurface s;
  s.color = vertexColors ? w[0] * v[0].color() + w[1] * v[1].color() + w[2] * v[2].color() : Color4(1);
  s.position = w[0] * v[0].position() + w[1] * v[1].position() + w[2] * v[2].position();
  const Vec3 normal = w[0] * v[0].normal() + w[1] * v[1].normal() + w[2] * v[2].normal();
  const Real len = glm::length(normal);
  s.normal = len > 0 ? (Real(1) / len) * normal : Vec3(0, 0, 1);  // as the SIMD rasterizer does
  // Two-sided lighting lights back faces with −N, as GL does per vertex.
  if (frame.lightModel.twoSided && !r.setup.frontFacing) s.normal = -s.normal;
  return s;
}

namespace {

// The clamped colour of a material at a point lit per pixel, its ambient occluded when the frame
// traces occlusion (as shadePoints scales it: SurfacePoints::ambientOpen).
Color4 litAt(const FrameContext& frame, const PointMaterial& point, const Vec3& position, const Vec3& normal,
             std::uint64_t seed) {
  const SurfaceGeometry s{position, normal, viewerDirection(position, frame.lightModel)};
  LightingTerms terms = evaluateTerms(frame.lights, frame.lightModel, point.material, point.model, s);
  if (frame.occlusion) {
    const Real* P[3] = {&position.x, &position.y, &position.z};
    const Real* N[3] = {&normal.x, &normal.y, &normal.z};
    Real open = 1;
    frame.occlusion->open(1, P, N, &seed, &open);
    terms.ambient = open * terms.ambient;
  }
  return clampedColor(terms, point.material, frame.lightModel.toneMap);
}

}  // namespace

Color4 shadePhongFragment(const FrameContext& frame, const Object& object, const DrawRecord& r,
                          const AttributeLayout& l, const std::array<Real, 3>& w, const Vec4* texel,
                          std::uint64_t seed) {
  const bool vertexColors = !object.mesh->colors.empty();
  const PhongSurface p = phongSurface(frame, vertexColors, r, l, w);
  const PointMaterial point = materialAt(object, frame.model, true, vertexColors ? &p.color : nullptr,
                                         [&](const Texture&) { return texel ? *texel : Vec4(1); });
  return litAt(frame, point, p.position, p.normal, seed);
}

TexturePoint texturePoint(const DrawRecord& r, const AttributeLayout& l, Real l0, Real l1, Real l2) {
  const TriangleSetup& t = r.setup;
  const Vec2 uv0 = VertexValues{r.vertex(0, l), l}.uv(), uv1 = VertexValues{r.vertex(1, l), l}.uv(),
             uv2 = VertexValues{r.vertex(2, l), l}.uv();
  const auto uvAt = [&](Real a, Real b, Real c) {
    const auto w = perspectiveWeights(t, a, b, c);
    return w[0] * uv0 + w[1] * uv1 + w[2] * uv2;
  };
  // Screen-space barycentrics are linear: one pixel right adds a·256/area, one up adds b·256/area.
  const Real step = Real(kSubpixelOne) / Real(t.area2);
  const Vec2 uv = uvAt(l0, l1, l2);
  const Vec2 dx = uvAt(l0 + Real(t.edge[0].a) * step, l1 + Real(t.edge[1].a) * step, l2 + Real(t.edge[2].a) * step) - uv;
  const Vec2 dy = uvAt(l0 + Real(t.edge[0].b) * step, l1 + Real(t.edge[1].b) * step, l2 + Real(t.edge[2].b) * step) - uv;
  return {uv, dx, dy};
}

Vec4 sampleAt(const Texture& texture, const TexturePoint& p) {
  const Vec2 size(Real(texture.width()), Real(texture.height()));
  return texture.sample(p.uv, std::max(glm::length(p.dx * size), glm::length(p.dy * size)));
}

MappedSurface mappedSurface(const FrameContext& frame, const Object& object, const DrawRecord& r,
                            const AttributeLayout& l, Real l0, Real l1, Real l2) {
  const bool vertexColors = !object.mesh->colors.empty();
  const PhongSurface p = phongSurface(frame, vertexColors, r, l, perspectiveWeights(r.setup, l0, l1, l2));
  const TexturePoint at = texturePoint(r, l, l0, l1, l2);
  MappedSurface s{p.position, p.normal,
                  materialAt(object, frame.model, true, vertexColors ? &p.color : nullptr,
                             [&](const Texture& texture) { return sampleAt(texture, at); })};
  if (s.point.normalTexel) {
    // The map bends the front side's normal; two-sided lighting's back faces take its opposite.
    const bool back = frame.lightModel.twoSided && !r.setup.frontFacing;
    const VertexValues v[3] = {{r.vertex(0, l), l}, {r.vertex(1, l), l}, {r.vertex(2, l), l}};
    const TangentFrame tangents =
        triangleTangents({v[0].position(), v[1].position(), v[2].position()}, {v[0].uv(), v[1].uv(), v[2].uv()});
    const Vec3 front = normalFromMap(back ? -p.normal : p.normal, tangents, *s.point.normalTexel, object.maps.normalScale);
    s.normal = back ? -front : front;
  }
  return s;
}

Color4 shadeMappedFragment(const FrameContext& frame, const MappedSurface& s, std::uint64_t seed) {
  return litAt(frame, s.point, s.position, s.normal, seed);
}

}  // namespace illum
