// The lighting equation over many surface points at once (SIMD, the widest the CPU has, chosen at
// run time): the vertex stage lights vertices with it, the per-pixel kernels lit pixels. The same
// lines (gl_lighting-inl.h) evaluate one point for the scalar reports, bit for bit alike.
#pragma once

#include <illum/lighting.h>

#include <cstddef>
#include <span>

namespace illum {

// What is the same for every point of a batch.
struct ShadeSetup {
  std::span<const EyeLight> lights;
  LightModel lightModel;
  LightingModel model = LightingModel::BlinnPhong;
  Material material;
};

// A batch of surface points as structure of arrays, in eye space.
struct SurfacePoints {
  std::size_t count = 0;
  const Real* position[3] = {};
  const Real* normal[3] = {};  // unit, of the side being lit (−N for a back face)
  const Real* color[4] = {};   // GL_COLOR_MATERIAL: each point's ambient and diffuse; null: the material's
};

// out[c][i] = channel c of point i's clamped colour (what clampedColor(evaluateTerms(...)) gives).
void shadePoints(const ShadeSetup& setup, const SurfacePoints& points, Real* const out[4]);

// The name of the SIMD target the dispatch chose on this CPU (for `illum bench` and -v).
const char* simdTargetName();

}  // namespace illum
