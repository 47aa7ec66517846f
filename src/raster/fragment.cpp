#include "raster/fragment.h"

namespace illum {

PhongSurface phongSurface(const FrameContext& frame, bool vertexColors, const TriangleSetup& t,
                          const std::array<Real, 3>& w) {
  const auto& v = t.vertex;
  PhongSurface s;
  s.color = vertexColors ? w[0] * v[0].color + w[1] * v[1].color + w[2] * v[2].color : Color4(1);
  s.position = w[0] * v[0].eyePosition + w[1] * v[1].eyePosition + w[2] * v[2].eyePosition;
  const Vec3 normal = w[0] * v[0].eyeNormal + w[1] * v[1].eyeNormal + w[2] * v[2].eyeNormal;
  const Real len = glm::length(normal);
  s.normal = len > 0 ? normal / len : Vec3(0, 0, 1);
  // Two-sided lighting lights back faces with −N, as GL does per vertex.
  if (frame.lightModel.twoSided && !t.frontFacing) s.normal = -s.normal;
  return s;
}

Color4 shadePhongFragment(const FrameContext& frame, const Material& baseMaterial, bool vertexColors,
                          const TriangleSetup& t, const std::array<Real, 3>& w) {
  const PhongSurface p = phongSurface(frame, vertexColors, t, w);
  const Material material = vertexColors ? withVertexColor(baseMaterial, p.color) : baseMaterial;
  const SurfaceGeometry s{p.position, p.normal, viewerDirection(p.position, frame.lightModel.localViewer)};
  return clampedColor(evaluateTerms(frame.lights, frame.lightModel, material, frame.model, s), material);
}

}  // namespace illum

namespace illum {

Vec4 sampleDiffuseTexture(const Texture& texture, const TriangleSetup& t, Real l0, Real l1, Real l2) {
  const auto uvAt = [&](Real a, Real b, Real c) {
    const auto w = perspectiveWeights(t, a, b, c);
    return w[0] * t.vertex[0].uv + w[1] * t.vertex[1].uv + w[2] * t.vertex[2].uv;
  };
  // Screen-space barycentrics are linear: one pixel right adds a·256/area, one up adds b·256/area.
  const Real step = Real(kSubpixelOne) / Real(t.area2);
  const Vec2 uv = uvAt(l0, l1, l2);
  const Vec2 dx = uvAt(l0 + Real(t.edge[0].a) * step, l1 + Real(t.edge[1].a) * step, l2 + Real(t.edge[2].a) * step) - uv;
  const Vec2 dy = uvAt(l0 + Real(t.edge[0].b) * step, l1 + Real(t.edge[1].b) * step, l2 + Real(t.edge[2].b) * step) - uv;
  const Vec2 size(Real(texture.width()), Real(texture.height()));
  const Real footprint = std::max(glm::length(dx * size), glm::length(dy * size));
  return texture.sample(uv, footprint);
}

}  // namespace illum
