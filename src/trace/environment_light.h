// An environment map as a light the path tracer samples (next-event estimation), so that a small,
// bright part of the sky (a sun, a window) lights a scene without the noise of waiting for
// BSDF-sampled rays to find it: directions are drawn in proportion to each texel's luminance (the
// mean of the bilinear lookups over its area, which blend its neighbours in) times the solid angle it
// covers (sin θ), by a row (marginal) then a column (conditional)
// cumulative distribution, as pbrt's infinite area light does.
#pragma once

#include <illum/environment.h>
#include <illum/real.h>

#include <vector>

namespace illum {

struct EnvironmentSample {
  Vec3 direction{0};  // unit, in the map's (world) space
  Real pdf = 0;       // per unit solid angle
};

class EnvironmentLight {
 public:
  explicit EnvironmentLight(const EnvironmentMap& map);

  // Whether any texel is bright: a black map is never sampled.
  bool empty() const { return !(total_ > 0); }
  // A direction for two uniform numbers in [0, 1).
  EnvironmentSample sample(Real u0, Real u1) const;
  // The solid-angle density `sample` draws world direction `d` (unit) with.
  Real pdf(const Vec3& d) const;

 private:
  int width_, height_;
  std::vector<Real> rowCdf_;     // height + 1 values, 0 .. total
  std::vector<Real> columnCdf_;  // per row, width + 1 values, 0 .. that row's weight
  std::vector<Real> weight_;     // luminance × sin θ of each texel, rows top to bottom
  Real total_ = 0;
};

}  // namespace illum
