// Emissive surfaces as area lights for the path tracer: every triangle of an object with an
// emission colour, chosen with probability ∝ area × luminance, a point on it uniformly.
#pragma once

#include "trace/ray_scene.h"

#include <vector>

namespace illum {

struct AreaLightSample {
  Vec3 position{0}, normal{0};  // eye space; the normal is the triangle's front, the side that shines
  Color3 radiance{0};
  Real pdfArea = 0;             // per unit area
};

class AreaLights {
 public:
  AreaLights(const Scene& scene, const RayScene& rays);
  bool empty() const { return cumulative_.empty(); }
  AreaLightSample sample(Real u0, Real u1, Real u2) const;
  // The density sample() gives a point of `object`, per unit area.
  Real pdfArea(std::uint32_t object) const;

 private:
  const RayScene& rays_;
  std::vector<std::uint32_t> object_, triangle_;
  std::vector<Real> cumulative_;   // of area × luminance, for choosing a triangle
  std::vector<Real> objectLuminance_;
  Real total_ = 0;
};

}  // namespace illum
