// Image-based lighting: an environment map lighting surfaces as the light arriving from every
// direction, the way Filament and three.js light with one, computed once per map:
//   diffuse   ρ/π · E(n), the irradiance E from the map's first nine spherical-harmonic
//             coefficients convolved with the clamped cosine (Ramamoorthi and Hanrahan 2001:
//             Â0 = π, Â1 = 2π/3, Â2 = π/4), stored divided by π;
//   specular  the split sum (Karis 2013): the map prefiltered with the GGX lobe of each roughness
//             (N = V = R), times f0·A + B from a table of the BRDF's integral over (N·V, roughness).
// The map's directions are world directions (+Y up, environment.h's latitude-longitude layout),
// turned by the scene's environment rotation; the renderer gives the rotation from its eye space.
#pragma once

#include <illum/environment.h>
#include <illum/lighting.h>
#include <illum/real.h>

#include <array>
#include <cstdint>
#include <type_traits>
#include <memory>
#include <vector>

namespace illum {

// A latitude-longitude image of linear RGB, sampled bilinearly (longitude wraps).
struct LatLongImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 floats a texel, rows top (+Y) to bottom (−Y)
  Vec3 texel(int x, int y) const;
  Vec3 bilinear(const Vec3& direction) const;  // direction unit, in the map's space
  Vec3 at(const Vec2& uv) const;               // uv as latLongPosition gives it
};

// Where unit direction d lies in a latitude-longitude image: u across (longitude from −Z towards
// +X), v down (latitude from +Y), both in [0, 1].
Vec2 latLongPosition(const Vec3& d);

// The map's direction through point (x, y) of a width × height latitude-longitude image (texel
// centres at half-integers).
Vec3 latLongDirection(Real x, Real y, int width, int height);

// Signed integers as wide as Real: the lanes' texel indices.
using RealIndex = std::conditional_t<sizeof(Real) == 4, std::int32_t, std::int64_t>;

class ImageLight {
 public:
  // The number of prefiltered levels: roughness k/(kLevels − 1) at level k.
  static constexpr int kLevels = 6;
  explicit ImageLight(const EnvironmentMap& map);

  // The light of `map`, computed once per process for the same texels (cached by their content:
  // the panels of a sheet, the frames of a turntable and every scene naming the map share it).
  static std::shared_ptr<const ImageLight> of(const EnvironmentMap& map);

  // E(n)/π for unit n in the map's space: the radiance a white Lambertian surface facing n reflects.
  Vec3 irradianceOverPi(const Vec3& n) const;
  // The nine coefficients of E/π, per channel, in the order (l, m) = (0,0) (1,−1) (1,0) (1,1)
  // (2,−2) (2,−1) (2,0) (2,1) (2,2), with x, y, z the map's axes.
  const std::array<Vec3, 9>& irradianceSh() const { return sh_; }
  // The map prefiltered by the GGX lobe of perceptual `roughness` ∈ [0, 1], towards r.
  Vec3 prefiltered(const Vec3& r, Real roughness) const;

  // The prefiltered levels, each an octahedral square (image_light-inl.h's OctahedralUv) of
  // levelSizes()[k]² texels from levelOffsets()[k] on, in one atlas per channel.
  const Real* atlas(int channel) const { return atlas_[std::size_t(channel)].data(); }
  const RealIndex* levelSizes() const { return levelSize_.data(); }
  const RealIndex* levelOffsets() const { return levelOffset_.data(); }

 private:
  std::array<Vec3, 9> sh_{};
  std::array<std::vector<Real>, 3> atlas_;
  std::array<RealIndex, kLevels> levelSize_{}, levelOffset_{};
};

// The split sum's second factor: (A, B) with ∫ f·cos over the hemisphere = f0·A + B for the GGX
// lobe of perceptual roughness (α = roughness², as MicrofacetAlpha) with Smith's correlated
// visibility and Schlick's Fresnel, at N·V; a table of kSplitSumTableSize² entries over N·V
// (columns) and roughness (rows), made once, read bilinearly (image_light-inl.h's SplitSum).
constexpr int kSplitSumTableSize = 32;
const Real* splitSumTable(int which);  // 0: A, 1: B
Vec2 splitSumDfg(Real NoV, Real roughness);

// An image light as one frame's renderer sees it: its rotation from eye space to the map's space,
// the scale of its radiance, and whether it lights classic (GL) materials in place of the light
// model's global ambient or physically based materials only.
struct EyeImageLight {
  std::shared_ptr<const ImageLight> light;
  Mat3 mapFromEye{1};
  Color3 scale{1};
  bool lightsClassic = true;
};

}  // namespace illum
