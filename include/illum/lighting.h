// The classic local lighting models as OpenGL 2.1 fixed-function defines them (§2.14.1):
// lights (glLight), materials (glMaterial), the light model (glLightModel) and the equation.
#pragma once

#include <illum/real.h>

#include <span>
#include <string_view>
#include <optional>

namespace illum {

using Color3 = Vec3;
using Color4 = Vec4;

// The specular lobe: blinn-phong (N·H)^n, phong (R·V)^n, or none (lambert).
enum class LightingModel { BlinnPhong, Phong, Lambert };
// Where the equation is evaluated: once per triangle, per vertex, or per pixel.
enum class Shading { Flat, Gouraud, Phong };

std::string_view toString(LightingModel model);
std::string_view toString(Shading shading);
std::optional<LightingModel> parseLightingModel(std::string_view name);
std::optional<Shading> parseShading(std::string_view name);

// glLight parameters with GL's defaults (every light, not only GL_LIGHT0, gets diffuse and
// specular white here, as the scene format says). Given in WORLD space.
struct Light {
  Vec4 position{0, 0, 1, 0};  // w = 0: directional, towards +xyz; w != 0: positional
  Color3 ambient{0, 0, 0};
  Color3 diffuse{1, 1, 1};
  Color3 specular{1, 1, 1};
  Vec3 attenuation{1, 0, 0};  // constant, linear, quadratic
  Vec3 spotDirection{0, 0, -1};
  Real spotExponent = 0;
  Real spotCutoff = 180;  // degrees; 180 means no spot
};

// glMaterial parameters with GL's defaults. Shininess is not capped at 128.
struct Material {
  Color4 ambient{0.2, 0.2, 0.2, 1};
  Color4 diffuse{0.8, 0.8, 0.8, 1};
  Color4 specular{0, 0, 0, 1};
  Color4 emission{0, 0, 0, 1};
  Real shininess = 0;
};

// glLightModel parameters with GL's defaults.
struct LightModel {
  Color3 ambient{0.2, 0.2, 0.2};
  bool localViewer = false;
  bool twoSided = false;
};

// A light as the equation sees it: in EYE space, as if glLight had been called with
// GL_MODELVIEW = viewFromWorld, with the cone's cosine precomputed.
struct EyeLight {
  Vec4 position{0, 0, 1, 0};
  Vec3 spotDirection{0, 0, -1};  // normalized
  Color3 ambient{0, 0, 0};
  Color3 diffuse{1, 1, 1};
  Color3 specular{1, 1, 1};
  Vec3 attenuation{1, 0, 0};
  Real spotExponent = 0;
  Real spotCutoff = 180;
  Real spotCosCutoff = -1;

  bool isPositional() const { return position.w != 0; }
  bool isSpot() const { return spotCutoff != 180; }
};

EyeLight toEyeSpace(const Light& light, const Mat4& viewFromWorld);

// The equation's four terms for one surface point, each unclamped, per channel.
struct LightingTerms {
  Color3 emission{0};
  Color3 ambient{0};
  Color3 diffuse{0};
  Color3 specular{0};
  Color3 sum() const { return emission + ambient + diffuse + specular; }
};

// The geometry of one evaluation, in eye space. N is the unit normal facing the viewer's side
// being lit (already negated for a back face), V the unit vector towards the viewer.
struct SurfaceGeometry {
  Vec3 position{0};
  Vec3 normal{0, 0, 1};
  Vec3 toViewer{0, 0, 1};
};

// Every intermediate of one light's contribution, for the reports that show the equation at work
// (`illum eval`, `--debug-pixel`): filled by the same code that computes the colour.
struct LightDetail {
  bool positional = false;
  Vec3 L{0};             // unit vector towards the light
  Real distance = 0;     // to a positional light (directional: 0, attenuation 1)
  Real attenuation = 1;  // 1 / (k_c + k_l·d + k_q·d²)
  Real spot = 1;         // the spot factor, 1 without a cone
  Real NoL = 0;
  Vec3 H{0};             // blinn-phong: normalize(L + V)
  Real NoH = 0;
  Vec3 R{0};             // phong: 2N(N·L) − L
  Real RoV = 0;
  Real lobe = 0;         // (N·H)^n or (R·V)^n; 0 when N·L ≤ 0 (f_i = 0) or lambert
  LightingTerms terms;   // this light's ambient, diffuse and specular, attenuation and spot applied
};

// One light's contribution (attenuation and spot applied) added into `terms`; with `detail`,
// every intermediate is recorded there too.
void accumulateLight(LightingTerms& terms, const EyeLight& light, const Material& material,
                     LightingModel model, const SurfaceGeometry& surface, LightDetail* detail = nullptr);

// The full equation: emission + global ambient + Σ lights. Terms unclamped.
LightingTerms evaluateTerms(std::span<const EyeLight> lights, const LightModel& lightModel,
                            const Material& material, LightingModel model,
                            const SurfaceGeometry& surface);

// The colour GL writes: each channel of the sum clamped to [0,1], alpha from the diffuse material.
Color4 clampedColor(const LightingTerms& terms, const Material& material);

// The viewer direction GL uses: (0,0,1) for an infinite viewer, normalize(-P) for a local one.
Vec3 viewerDirection(const Vec3& eyePosition, bool localViewer);

}  // namespace illum
