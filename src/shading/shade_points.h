// The lighting equation over many surface points at once (SIMD, the widest the CPU has, chosen at
// run time): the vertex stage lights vertices with it, the per-pixel kernels lit pixels. The same
// lines (gl_lighting-inl.h) evaluate one point for the scalar reports, bit for bit alike.
#pragma once

#include <illum/lighting.h>

#include <cstddef>
#include <cstdint>
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
  // Ambient occlusion: the open share of each point's hemisphere, which scales its ambient term
  // (the light arriving from everywhere); null: all open.
  const Real* ambientOpen = nullptr;
  // glTF's maps at each point (withMapTexels's result): a physically based material's metallic
  // and roughness (both or neither), and the emission colour; null: the material's own.
  const Real* metallic = nullptr;
  const Real* roughness = nullptr;
  const Real* emission[3] = {};
};

// out[c][i] = channel c of point i's clamped colour (what clampedColor(evaluateTerms(...)) gives).
void shadePoints(const ShadeSetup& setup, const SurfacePoints& points, Real* const out[4]);

// Lights the points that have an owner (owner[i] != kNoOwner) with that owner's setup (without
// ambient occlusion: frames that trace it light their points by shadePoints), and with the
// points' own colours where colored[owner]; writes each lit point's colour to rgba[i] as an RGBA8
// word (toUnorm8 per channel, R in the lowest byte). The arrays are read in whole vectors: they
// must hold `count` rounded up to a multiple of 16 values. Float channels only (ILLUM_DOUBLE=OFF).
constexpr std::uint32_t kNoOwner = 0xFFFFFFFF;
void shadeOwnedPoints(std::span<const ShadeSetup> setups, std::span<const std::uint8_t> colored,
                      const SurfacePoints& points, const std::uint32_t* owner, std::uint32_t* rgba);

// The name of the SIMD target the dispatch chose on this CPU (for `illum bench` and -v).
const char* simdTargetName();

}  // namespace illum
