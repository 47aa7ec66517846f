// The classic local lighting models as OpenGL 2.1 fixed-function defines them (§2.14.1):
// lights (glLight), materials (glMaterial), the light model (glLightModel) and the equation.
#pragma once

#include <illum/display.h>
#include <illum/real.h>

#include <span>
#include <string>
#include <string_view>
#include <memory>
#include <optional>

namespace illum {

// The specular lobe: blinn-phong (N·H)^n, phong (R·V)^n, none (lambert), or Cook and Torrance's
// microfacet reflectance D·F·G / (4 N·L N·V) (cook-torrance, physically based). And the two
// models the seeds' history starts with: wylie (Wylie et al. 1967, intensity ∝ 1/d from the light,
// no angle) and bouknight (Bouknight 1970, ambient + Lambert's cosine law, no attenuation).
enum class LightingModel { BlinnPhong, Phong, Lambert, CookTorrance, Wylie, Bouknight };
// Every model, in the order their names are listed.
inline constexpr LightingModel kLightingModels[] = {LightingModel::BlinnPhong, LightingModel::Phong,
                                                     LightingModel::Lambert,    LightingModel::CookTorrance,
                                                     LightingModel::Wylie,      LightingModel::Bouknight};
// Where the equation is evaluated: once per triangle, per vertex, or per pixel.
enum class Shading { Flat, Gouraud, Phong };

std::string_view toString(LightingModel model);
std::string_view toString(Shading shading);
std::optional<LightingModel> parseLightingModel(std::string_view name);
// "blinn-phong, phong, ... or bouknight" (each in double quotes with `quoted`), for messages.
std::string lightingModelNames(bool quoted = false);
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

// The microfacet distribution of the cook-torrance model: Trowbridge-Reitz/GGX (Walter et al.
// 2007, glTF's) or Beckmann's (Cook and Torrance 1982).
enum class Microfacet { GGX, Beckmann };

// What the cook-torrance model reads: glTF's metallic-roughness parameters.
struct PhysicalMaterial {
  Color3 baseColor{0.8, 0.8, 0.8};  // the diffuse albedo of a dielectric, the reflectance of a metal
  Real metallic = 0;                // 0 dielectric .. 1 metal
  Real roughness = 1;               // perceptual roughness; the distribution's α = roughness²
  Color3 f0{0.04, 0.04, 0.04};      // a dielectric's reflectance at normal incidence, ((n−1)/(n+1))²
  Microfacet distribution = Microfacet::GGX;
  bool operator==(const PhysicalMaterial&) const = default;
};

// glMaterial parameters with GL's defaults (shininess is not capped at 128), or a physically
// based material. Every model draws every material: a physically based one carries GL
// parameters derived from it (glFromPhysical, called by whoever makes one), and a GL one is seen
// by cook-torrance through physicalOf. `model`, when set, is this material's lighting model.
struct Material {
  Color4 ambient{0.2, 0.2, 0.2, 1};
  Color4 diffuse{0.8, 0.8, 0.8, 1};  // its alpha is the material's, under every model
  Color4 specular{0, 0, 0, 1};
  Color4 emission{0, 0, 0, 1};       // under every model
  Real shininess = 0;
  bool physicallyBased = false;      // `physical` was given, the GL parameters derived from it
  PhysicalMaterial physical;
  std::optional<LightingModel> model;
  bool operator==(const Material&) const = default;
};

// A GL material as cook-torrance sees it: base colour = diffuse, a dielectric whose f0 = 0.16·s²
// for the specular colour s (Filament's reflectance mapping: s = 0.5 gives 0.04), α = √(2/(n+2))
// (the Blinn-Phong exponent n that matches a Beckmann lobe of roughness α, Walter et al. 2007).
PhysicalMaterial physicalFromGl(const Material& m);
// Makes `m` physically based with `p` and derives its GL parameters, as the classic models see
// it: ambient = diffuse = base·(1−metallic), specular = 2.5·√f0 (physicalFromGl's mapping
// reversed) mixed towards the base colour by metallic, shininess n = 2/α² − 2 (emission and alpha
// are kept).
void glFromPhysical(Material& m, const PhysicalMaterial& p);
// What cook-torrance reads of any material.
inline PhysicalMaterial physicalOf(const Material& m) { return m.physicallyBased ? m.physical : physicalFromGl(m); }
// What the lighting model `model` reads of the physically based description: all of it for
// cook-torrance, nothing for the classic models (which read the GL colours).
inline PhysicalMaterial physicalFor(const Material& m, LightingModel model) {
  return model == LightingModel::CookTorrance ? physicalOf(m) : PhysicalMaterial{};
}
// The material GL uses at a vertex with colour `c` under GL_COLOR_MATERIAL(GL_AMBIENT_AND_DIFFUSE);
// for cook-torrance the colour is the base colour.
inline Material withVertexColor(Material m, const Color4& c) {
  m.ambient = c;
  m.diffuse = c;
  m.physical.baseColor = Color3(c);
  return m;
}

// The lighting model that draws `m` in a scene whose model is `sceneModel`.
inline LightingModel modelOf(const Material& m, LightingModel sceneModel) { return m.model.value_or(sceneModel); }

// How the equation is computed: as OpenGL does (§2.14.1), or as a lecture note does (seed 001):
//   note-shader    its Blinn-Phong shader, pixel = mat.ambient + (mat.diffuse + specular) ×
//                  Ld·max(N·L, 0): the specular scaled by the light's diffuse strength and N·L too,
//                  the ambient the material's alone (no emission, no light or global ambient);
//   note-half-sum  its H = (L + V) / 2 taken without normalising it: N·H smaller than GL's, so
//                  (N·H)ⁿ falls off faster (the rest is GL's);
//   note-world-space  seed 004's lighting in world space, V from each point to the camera's
//                  position: GL's local viewer (the rigid view transform keeps every angle, so
//                  the viewer's direction is the whole difference from GL's eye space, where an
//                  infinite viewer's V is (0, 0, 1) everywhere).
// The shader and the half sum change the models the note teaches (blinn-phong, phong, lambert);
// the others are computed as they are. World space changes V for every model.
enum class Convention { GL, NoteShader, NoteHalfSum, NoteWorldSpace };
inline constexpr Convention kConventions[] = {Convention::GL, Convention::NoteShader, Convention::NoteHalfSum,
                                              Convention::NoteWorldSpace};
std::string_view toString(Convention convention);
std::optional<Convention> parseConvention(std::string_view name);
// "gl, note-shader or note-half-sum" (each in double quotes with `quoted`), for messages.
std::string conventionNames(bool quoted = false);
// Whether `convention` changes what `model` computes.
inline bool follows(LightingModel model, Convention convention) {
  if (convention == Convention::NoteWorldSpace) return true;
  return convention != Convention::GL &&
         (model == LightingModel::BlinnPhong || model == LightingModel::Phong || model == LightingModel::Lambert);
}

// glLightModel parameters with GL's defaults, and the convention the equation follows.
struct EyeImageLight;
struct LightModel {
  Color3 ambient{0.2, 0.2, 0.2};
  bool localViewer = false;
  bool twoSided = false;
  Convention convention = Convention::GL;
  // An environment map's image-based light, as the renderer drawing a frame sets it (the scene's
  // "environment_lighting"): physically based materials take their ambient and a reflection of the
  // map from it, and GL materials, where it lights them, take it in place of `ambient`.
  std::shared_ptr<const EyeImageLight> environment;
  // The display's tone map, as the rasterizer's frame sets it (the scene's "tone_map"): applied to
  // each lit colour before GL's clamp, since the framebuffer keeps 8-bit display values and a
  // radiance above 1 would be lost in it. None everywhere else (the ray tracers tone map each
  // pixel's radiance instead).
  ToneMap toneMap = ToneMap::None;
};

// Whether V points from each point to the eye (GL_LIGHT_MODEL_LOCAL_VIEWER, or seed 004's world
// space) rather than along +z.
inline bool viewerIsLocal(const LightModel& lm) { return lm.localViewer || lm.convention == Convention::NoteWorldSpace; }

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
  // Whether it lights highlights at all (the preview rig's fill light does not).
  bool hasSpecular() const { return specular != Color3(0); }
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
  Vec3 H{0};             // blinn-phong: normalize(L + V) ((L + V)/2 under note-half-sum)
  Real NoH = 0;
  Vec3 R{0};             // phong: 2N(N·L) − L
  Real RoV = 0;
  Real lobe = 0;         // (N·H)^n or (R·V)^n; 0 when N·L ≤ 0 (f_i = 0) or lambert
  // cook-torrance: its terms at this light (N·V, V·H, and D, the visibility G/(4 N·L N·V), F)
  Real NoV = 0, VoH = 0, D = 0, visibility = 0;
  Color3 F{0};
  LightingTerms terms;   // this light's ambient, diffuse and specular, attenuation and spot applied
};

// One light's contribution (attenuation and spot applied) added into `terms`; with `detail`,
// every intermediate is recorded there too. For one light this is exactly evaluateTerms' sum; for
// several, evaluateTerms sums the lights before the material's colours multiply them, which may
// round the last bit differently from adding each light's contribution.
// Under a note's `convention` (LightModel::convention), as that note computes it.
void accumulateLight(LightingTerms& terms, const EyeLight& light, const Material& material,
                     LightingModel model, const SurfaceGeometry& surface, LightDetail* detail = nullptr,
                     Convention convention = Convention::GL);

// The full equation: emission + global ambient + Σ lights. Terms unclamped.
LightingTerms evaluateTerms(std::span<const EyeLight> lights, const LightModel& lightModel,
                            const Material& material, LightingModel model,
                            const SurfaceGeometry& surface);

// The colour GL writes: each channel of the sum clamped to [0,1] (after `toneMap`, where the
// rasterizer's frame has one: LightModel::toneMap), alpha from the diffuse material.
Color4 clampedColor(const LightingTerms& terms, const Material& material, ToneMap toneMap = ToneMap::None);

// The viewer direction GL uses: (0,0,1) for an infinite viewer, normalize(-P) for a local one
// (viewerIsLocal).
Vec3 viewerDirection(const Vec3& eyePosition, const LightModel& lightModel);

}  // namespace illum
