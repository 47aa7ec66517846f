#include "raster/fragment.h"

namespace illum {

Color4 shadePhongFragment(const FrameContext& frame, const Material& material, const TriangleSetup& t,
                          const std::array<Real, 3>& w) {
  const auto& v = t.vertex;
  const Vec3 position = w[0] * v[0]->eyePosition + w[1] * v[1]->eyePosition + w[2] * v[2]->eyePosition;
  Vec3 normal = w[0] * v[0]->eyeNormal + w[1] * v[1]->eyeNormal + w[2] * v[2]->eyeNormal;
  const Real len = glm::length(normal);
  normal = len > 0 ? normal / len : Vec3(0, 0, 1);
  // Two-sided lighting lights back faces with −N, as GL does per vertex.
  if (frame.lightModel.twoSided && !t.frontFacing) normal = -normal;
  const SurfaceGeometry s{position, normal, viewerDirection(position, frame.lightModel.localViewer)};
  return clampedColor(evaluateTerms(frame.lights, frame.lightModel, material, frame.model, s), material);
}

}  // namespace illum
