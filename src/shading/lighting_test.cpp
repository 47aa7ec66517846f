// Closed forms for every rule of the OpenGL 2.1 §2.14.1 lighting equation.
#include <illum/lighting.h>

#include "shading/brdf.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace illum {
namespace {

constexpr Real kTol = Real(1e-5);

Vec3 dirAt(Real degrees) {  // unit vector in the XZ plane, `degrees` away from +Z towards +X
  const Real t = glm::radians(degrees);
  return {std::sin(t), 0, std::cos(t)};
}

EyeLight directional(const Vec3& towards) {
  EyeLight l;
  l.position = Vec4(towards, 0);
  return l;
}

Material whiteMaterial(Real shininess = 0) {
  Material m;
  m.ambient = {0, 0, 0, 1};
  m.diffuse = {1, 1, 1, 1};
  m.specular = {1, 1, 1, 1};
  m.shininess = shininess;
  return m;
}

LightingTerms oneLight(const EyeLight& light, const Material& m, LightingModel model, const SurfaceGeometry& s) {
  LightModel lm;
  lm.ambient = Color3(0);
  return evaluateTerms({&light, 1}, lm, m, model, s);
}

void expectColor(const Color3& actual, const Color3& expected, Real tol = kTol) {
  EXPECT_NEAR(actual.r, expected.r, tol);
  EXPECT_NEAR(actual.g, expected.g, tol);
  EXPECT_NEAR(actual.b, expected.b, tol);
}

TEST(Lambert, SixtyDegreesIsHalfOfZero) {
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Real at0 = oneLight(directional(dirAt(0)), whiteMaterial(), LightingModel::Lambert, s).diffuse.r;
  const Real at60 = oneLight(directional(dirAt(60)), whiteMaterial(), LightingModel::Lambert, s).diffuse.r;
  EXPECT_NEAR(at0, 1, kTol);
  EXPECT_NEAR(at60, 0.5, kTol);
}

TEST(Lambert, NoLightFromBehindAndNoSpecular) {
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const auto t = oneLight(directional(dirAt(120)), whiteMaterial(10), LightingModel::Lambert, s);
  expectColor(t.diffuse, Color3(0));
  const auto front = oneLight(directional(dirAt(0)), whiteMaterial(10), LightingModel::Lambert, s);
  expectColor(front.specular, Color3(0));
}

TEST(Lambert, NamedTermClampsNegativeCosines) {
  EXPECT_EQ(Fd_LambertCosine(Real(-0.3)), 0);
  EXPECT_NEAR(Fd_LambertCosine(Real(0.25)), 0.25, kTol);
}

// The exercise at the end of the "Colored light" part of seed 003: D = 1, θ(N,L) = 30°,
// φ(R,V) = 0°, shininess 2, per-channel light and material colours.
TEST(SeedExercise, ColoredLightTable) {
  EyeLight light;
  const Vec3 L = dirAt(30);
  light.position = Vec4(L, 1);  // positional at distance 1
  light.ambient = {0.4, 0.9, 0.2};
  light.diffuse = {0.3, 1.0, 1.0};
  light.specular = {1.0, 1.0, 1.0};
  Material m;
  m.ambient = {0.9, 0.9, 0.1, 1};
  m.diffuse = {0.8, 1.0, 0.8, 1};
  m.specular = {0.0, 1.0, 0.6, 1};
  m.shininess = 2;
  const Vec3 R(-L.x, 0, L.z);  // viewer on the mirror direction: φ = 0
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), R};
  const auto t = oneLight(light, m, LightingModel::Phong, s);
  const Real c30 = std::sqrt(Real(3)) / 2;
  expectColor(t.emission, {0, 0, 0});
  expectColor(t.ambient, {0.36, 0.81, 0.02});
  expectColor(t.diffuse, {0.24 * c30, 1.0 * c30, 0.8 * c30});
  expectColor(t.specular, {0.0, 1.0, 0.6});
  expectColor(Color3(clampedColor(t, m)), {0.36 + 0.24 * c30, 1, 1});
}

TEST(BlinnPhong, PeakWhereNEqualsH) {
  // Light 40° from N; sweep the viewer in the plane of incidence. N·H = 1 exactly when V is L
  // mirrored about N, at −40°.
  const EyeLight light = directional(dirAt(40));
  Real best = -1, bestAngle = 0;
  for (int a = -89; a <= 89; ++a) {
    const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), dirAt(Real(a))};
    const Real spec = oneLight(light, whiteMaterial(30), LightingModel::BlinnPhong, s).specular.r;
    if (spec > best) { best = spec; bestAngle = Real(a); }
  }
  EXPECT_EQ(bestAngle, -40);
  EXPECT_NEAR(best, 1, kTol);
}

TEST(BlinnPhong, HalfwayVectorClosedForm) {
  // L at 60°, V at 0°: H is 30° from N, so the lobe is cos(30°)^n.
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Real spec = oneLight(directional(dirAt(60)), whiteMaterial(8), LightingModel::BlinnPhong, s).specular.r;
  EXPECT_NEAR(spec, std::pow(std::cos(glm::radians(Real(30))), Real(8)), kTol);
}

TEST(Phong, ReflectionVectorClosedForm) {
  // L at 30°: R at −30°; V at 0° is 30° from R, so the lobe is cos(30°)^n.
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Real spec = oneLight(directional(dirAt(30)), whiteMaterial(5), LightingModel::Phong, s).specular.r;
  EXPECT_NEAR(spec, std::pow(std::cos(glm::radians(Real(30))), Real(5)), kTol);
  // Beyond 90° between R and V nothing is reflected.
  const SurfaceGeometry far{Vec3(0), Vec3(0, 0, 1), dirAt(80)};
  EXPECT_EQ(oneLight(directional(dirAt(30)), whiteMaterial(5), LightingModel::Phong, far).specular.r, 0);
}

TEST(Specular, ZeroWhenLightIsBehindTheSurface) {
  // N·L < 0: f = 0, even with shininess 0 where the lobe alone would be 0^0 = 1.
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  for (LightingModel model : {LightingModel::BlinnPhong, LightingModel::Phong}) {
    EXPECT_EQ(oneLight(directional(dirAt(100)), whiteMaterial(0), model, s).specular.r, 0);
    EXPECT_EQ(oneLight(directional(Vec3(1, 0, 0)), whiteMaterial(0), model, s).specular.r, 0);  // N·L = 0 exactly
  }
}

TEST(Specular, ZeroToTheZeroIsOne) {
  // Shininess 0 with N·H = 0 (H ⟂ N): GL defines 0^0 = 1, so the full specular colour shows.
  EXPECT_EQ(Fs_BlinnPhong(0, 0), 1);
  EXPECT_EQ(Fs_Phong(0, 0), 1);
  EXPECT_EQ(Fs_BlinnPhong(Real(-0.5), 0), 1);
  // L at 45° and V at 135° give H = (L+V)/|L+V| ⟂ N.
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), dirAt(135)};
  const auto t = oneLight(directional(dirAt(45)), whiteMaterial(0), LightingModel::BlinnPhong, s);
  EXPECT_NEAR(t.specular.r, 1, kTol);
  // With any positive shininess the same geometry reflects nothing.
  EXPECT_NEAR(oneLight(directional(dirAt(45)), whiteMaterial(1), LightingModel::BlinnPhong, s).specular.r, 0, kTol);
}

TEST(Specular, LightOppositeViewerIsDefined) {
  // L = −V leaves H undefined; illum takes N·H = 0: no NaN, no highlight for n > 0.
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), -dirAt(30)};
  const auto t = oneLight(directional(dirAt(30)), whiteMaterial(10), LightingModel::BlinnPhong, s);
  EXPECT_EQ(t.specular.r, 0);
  EXPECT_FALSE(std::isnan(t.sum().r));
}

TEST(Attenuation, AtDistanceTwo) {
  EXPECT_NEAR(distanceAttenuation({1, 0, 0}, 2), 1, kTol);
  EXPECT_NEAR(distanceAttenuation({0, 1, 0}, 2), 0.5, kTol);
  EXPECT_NEAR(distanceAttenuation({0, 0, 1}, 2), 0.25, kTol);  // the inverse-square law I/r²
  EXPECT_NEAR(distanceAttenuation({1, 1, 1}, 2), 1.0 / 7, kTol);
  // Through the equation: a positional light 2 units straight above the point.
  EyeLight light;
  light.position = {0, 0, 2, 1};
  light.attenuation = {0, 0, 1};
  light.ambient = {1, 1, 1};
  Material m = whiteMaterial();
  m.ambient = {1, 1, 1, 1};
  const auto t = oneLight(light, m, LightingModel::Lambert, {Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  EXPECT_NEAR(t.diffuse.r, 0.25, kTol);
  EXPECT_NEAR(t.ambient.r, 0.25, kTol);  // the light's ambient is attenuated too
}

TEST(Attenuation, OnlyForPositionalLights) {
  EyeLight light = directional(Vec3(0, 0, 5));
  light.attenuation = {0, 0, 1};
  const auto t = oneLight(light, whiteMaterial(), LightingModel::Lambert, {Vec3(0, 0, -10), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  EXPECT_NEAR(t.diffuse.r, 1, kTol);
}

EyeLight spotAbove(Real cutoff, Real exponent) {
  Light l;
  l.position = {0, 0, 1, 1};
  l.spotDirection = {0, 0, -1};
  l.spotCutoff = cutoff;
  l.spotExponent = exponent;
  l.ambient = {1, 1, 1};
  return toEyeSpace(l, Mat4(1));
}

TEST(Spot, ConeEdge) {
  // A spot 1 unit above the plane z = 0 pointing down with a 30° cone: the edge is at
  // x = tan 30°. Just inside is lit with cos^e, just outside nothing, ambient included.
  const EyeLight light = spotAbove(30, 2);
  const Material m = whiteMaterial();
  const Real edge = std::tan(glm::radians(Real(30)));
  const auto inside = oneLight(light, m, LightingModel::Lambert, {Vec3(edge * Real(0.99), 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  const auto outside = oneLight(light, m, LightingModel::Lambert, {Vec3(edge * Real(1.01), 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  const Real cosInside = 1 / std::sqrt(1 + (edge * Real(0.99)) * (edge * Real(0.99)));
  EXPECT_NEAR(inside.diffuse.r, cosInside * cosInside * cosInside, kTol);  // spot cos² × Lambert cos
  EXPECT_EQ(outside.diffuse.r, 0);
  EXPECT_EQ(outside.ambient.r, 0);  // the light's ambient is spotted too
  EXPECT_EQ(spotFactor(Real(0.5), Real(0.6), 1), 0);
  EXPECT_NEAR(spotFactor(Real(0.7), Real(0.6), 2), 0.49, kTol);
}

TEST(Spot, AppliesToDirectionalLights) {
  Light l;
  l.position = {0, 0, 1, 0};
  l.spotCutoff = 45;
  l.spotDirection = {1, 0, 0};  // −L·S = 0: outside a 45° cone
  const auto t = oneLight(toEyeSpace(l, Mat4(1)), whiteMaterial(), LightingModel::Lambert, {Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  EXPECT_EQ(t.diffuse.r, 0);
  l.spotDirection = {0, 0, -1};  // −L·S = 1: on the axis
  const auto lit = oneLight(toEyeSpace(l, Mat4(1)), whiteMaterial(), LightingModel::Lambert, {Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  EXPECT_NEAR(lit.diffuse.r, 1, kTol);
}

TEST(Spot, NoSpotAtCutoff180) {
  const EyeLight light = spotAbove(180, 128);
  const auto t = oneLight(light, whiteMaterial(), LightingModel::Lambert, {Vec3(100, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1)});
  EXPECT_GT(t.diffuse.r, 0);
}

TEST(Viewer, LocalVersusInfinite) {
  LightModel infinite, local, worldSpace;
  local.localViewer = true;
  worldSpace.convention = Convention::NoteWorldSpace;
  EXPECT_EQ(viewerDirection(Vec3(3, 4, -5), infinite), Vec3(0, 0, 1));
  expectColor(viewerDirection(Vec3(3, 0, -4), local), {-0.6, 0, 0.8});
  // Seed 004's world space: V towards the camera's position, which is the local viewer's.
  expectColor(viewerDirection(Vec3(3, 0, -4), worldSpace), {-0.6, 0, 0.8});
  // At the eye itself the direction is undefined; the infinite viewer's is taken.
  EXPECT_EQ(viewerDirection(Vec3(0), local), Vec3(0, 0, 1));
}

// Seed 001's shader and half sum, closed forms: N = V = +z, a directional light 60° from N.
TEST(Equation, TheNotesConventions) {
  const Real c60 = Real(0.5), s60 = std::sqrt(Real(3)) / 2;
  EyeLight light;
  light.position = Vec4(s60, 0, c60, 0);
  light.ambient = Color3(0.3);
  light.diffuse = Color3(0.5);
  light.specular = Color3(1);
  Material m;
  m.specular = Color4(1);
  m.emission = Color4(0.1, 0.1, 0.1, 1);
  m.shininess = 20;
  const SurfaceGeometry s{Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)};
  const Real lobe = std::pow(std::cos(glm::radians(Real(30))), Real(20));
  LightModel lm;
  lm.convention = Convention::NoteShader;
  const EyeLight lights[] = {light};
  const LightingTerms shader = evaluateTerms(lights, lm, m, LightingModel::BlinnPhong, s);
  expectColor(shader.emission, Color3(0));                   // no emission
  expectColor(shader.ambient, Color3(0.2));                  // the material's ambient alone
  expectColor(shader.diffuse, Color3(0.8 * 0.5 * c60));      // kd · Ld·(N·L)
  expectColor(shader.specular, Color3(lobe * 0.5 * c60));    // ks · (N·H)ⁿ · Ld·(N·L): Ld, not Ls
  lm.convention = Convention::NoteHalfSum;
  const LightingTerms half = evaluateTerms(lights, lm, m, LightingModel::BlinnPhong, s);
  expectColor(half.specular, Color3(std::pow(Real(0.75), Real(20))));  // N·(L + V)/2 = (1/2 + 1)/2
  expectColor(half.ambient, Color3(0.2 * 0.2 + 0.2 * 0.3));          // GL's ambient terms
  // The models the note does not teach are as they are.
  lm.convention = Convention::NoteShader;
  Material physical = m;
  const LightingTerms ct = evaluateTerms(lights, lm, physical, LightingModel::CookTorrance, s);
  lm.convention = Convention::GL;
  const LightingTerms ctGl = evaluateTerms(lights, lm, physical, LightingModel::CookTorrance, s);
  EXPECT_EQ(ct.sum(), ctGl.sum());
}

TEST(Equation, EmissionAndGlobalAmbientAndClamp) {
  Material m;
  m.emission = {0.1, 0.2, 0.3, 1};
  m.ambient = {0.5, 0.5, 0.5, 1};
  m.diffuse = {1, 1, 1, 0.25};
  LightModel lm;  // default global ambient 0.2
  const EyeLight light = directional({0, 0, 1});
  const auto t = evaluateTerms({&light, 1}, lm, m, LightingModel::BlinnPhong, {Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  expectColor(t.emission, {0.1, 0.2, 0.3});
  expectColor(t.ambient, {0.1, 0.1, 0.1});
  const Color4 c = clampedColor(t, m);
  EXPECT_EQ(c.r, 1);  // 0.1 + 0.1 + 1 clamps
  EXPECT_NEAR(c.a, 0.25, kTol);  // alpha is the diffuse material's
}

TEST(Equation, SeveralColouredLightsAddPerChannel) {
  EyeLight red = directional({0, 0, 1}), blue = directional({0, 0, 1});
  red.diffuse = {1, 0, 0};
  blue.diffuse = {0, 0, 0.5};
  const std::vector<EyeLight> lights = {red, blue};
  LightModel lm;
  lm.ambient = Color3(0);
  const auto t = evaluateTerms(lights, lm, whiteMaterial(), LightingModel::Lambert, {Vec3(0), Vec3(0, 0, 1), Vec3(0, 0, 1)});
  expectColor(t.diffuse, {1, 0, 0.5});
}

// The material's colours multiply the lights' sums (gl_lighting-inl.h): the same equation as
// Σ_i att_i·spot_i·[a_cm·a_cli + ...], light by light. With one light the two are the same
// numbers exactly (what `illum eval` reports is what the renderer computes); with several, each
// light's share (accumulateLight, as --debug-pixel lists them) adds up to the total to rounding.
TEST(Equation, MaterialColoursMultiplyTheLightsSums) {
  Material m;
  m.ambient = {0.3, 0.25, 0.2, 1};
  m.diffuse = {0.2, 0.8, 0.5, 1};
  m.specular = {0.8, 0.7, 0.6, 1};
  m.shininess = 28;
  LightModel lm;
  lm.ambient = Color3(0.1);
  std::vector<EyeLight> lights;
  for (int i = 0; i < 3; ++i) {
    EyeLight l;
    l.position = {Real(2 - 2 * i), Real(1 + i), 3, 1};
    l.ambient = Color3(Real(0.02 * (i + 1)));
    l.diffuse = {Real(0.6 - 0.1 * i), 0.54, Real(0.18 + 0.2 * i)};
    l.specular = Color3(0.7);
    l.attenuation = {1, 0.05, 0.01};
    lights.push_back(l);
  }
  const SurfaceGeometry s{Vec3(0.1, -0.2, 0.3), glm::normalize(Vec3(0.2, 0.3, 1)), Vec3(0, 0, 1)};
  for (const LightingModel model : {LightingModel::Lambert, LightingModel::Phong, LightingModel::BlinnPhong}) {
    LightingTerms shares = evaluateTerms({}, lm, m, model, s);
    for (const EyeLight& l : lights) {
      LightingTerms one = evaluateTerms({}, lm, m, model, s);
      accumulateLight(one, l, m, model, s);
      const LightingTerms whole = evaluateTerms({&l, 1}, lm, m, model, s);
      EXPECT_EQ(one.ambient, whole.ambient);
      EXPECT_EQ(one.diffuse, whole.diffuse);
      EXPECT_EQ(one.specular, whole.specular);
      accumulateLight(shares, l, m, model, s);
    }
    const LightingTerms sum = evaluateTerms(lights, lm, m, model, s);
    expectColor(sum.ambient, shares.ambient, Real(1e-6));
    expectColor(sum.diffuse, shares.diffuse, Real(1e-6));
    expectColor(sum.specular, shares.specular, Real(1e-6));
    // The closed form of the ambient channel: a_cm·a_cs + a_cm·Σ att_i·a_cli.
    Real lightAmbient = 0;
    for (const EyeLight& l : lights) {
      const Real d = glm::length(Vec3(l.position) - s.position);
      lightAmbient += l.ambient.r / (1 + Real(0.05) * d + Real(0.01) * d * d);
    }
    EXPECT_NEAR(sum.ambient.r, m.ambient.r * (Real(0.1) + lightAmbient), Real(1e-6));
    if (model != LightingModel::Lambert) {
      EXPECT_GT(sum.specular.g, 0);  // a highlight to compare
    }
  }
}

TEST(Lights, TransformedToEyeSpaceLikeGlLight) {
  // A view that turns the world 90° about Y and moves it 5 units away.
  Mat4 view = glm::translate(Mat4(1), Vec3(0, 0, -5));
  view = glm::rotate(view, glm::radians(Real(90)), Vec3(0, 1, 0));
  Light l;
  l.position = {1, 0, 0, 1};
  l.spotDirection = {0, 0, -2};
  const EyeLight e = toEyeSpace(l, view);
  EXPECT_NEAR(e.position.x, 0, kTol);
  EXPECT_NEAR(e.position.z, -6, kTol);
  EXPECT_NEAR(e.position.w, 1, kTol);
  expectColor(e.spotDirection, {-1, 0, 0});  // upper 3×3 only, then normalized
  EXPECT_NEAR(e.spotCosCutoff, -2, kTol);  // no spot
}

TEST(Models, ParseAndName) {
  EXPECT_EQ(parseLightingModel("phong"), LightingModel::Phong);
  EXPECT_EQ(parseLightingModel("Phong"), std::nullopt);
  EXPECT_EQ(toString(LightingModel::BlinnPhong), "blinn-phong");
  EXPECT_EQ(parseShading("gouraud"), Shading::Gouraud);
  EXPECT_EQ(toString(Shading::Flat), "flat");
}

}  // namespace
}  // namespace illum

namespace illum {
namespace {

// Wylie et al. (1967): intensity inversely proportional to the distance from the light, whatever
// the angle; no ambient light, no highlight.
TEST(Wylie, IntensityFallsAsOneOverDistanceWithNoAngle) {
  EyeLight light;
  light.position = {0, 0, 4, 1};  // 4 units in front of the point
  light.diffuse = Color3(2);
  light.attenuation = {0, 0, 1};  // GL's attenuation is not Wylie's: ignored
  Material m;
  m.diffuse = {0.5f, 0.25f, 1, 1};
  m.specular = {1, 1, 1, 1};
  m.shininess = 10;
  LightModel lm;  // its ambient (0.2) is not Wylie's either
  for (const Vec3& N : {Vec3(0, 0, 1), glm::normalize(Vec3(1, 0, 1)), Vec3(1, 0, 0)}) {
    const LightingTerms t = evaluateTerms({&light, 1}, lm, m, LightingModel::Wylie, {Vec3(0), N, Vec3(0, 0, 1)});
    EXPECT_NEAR(t.diffuse.r, 2 * 0.5 / 4, kTol);
    EXPECT_NEAR(t.diffuse.g, 2 * 0.25 / 4, kTol);
    EXPECT_EQ(t.ambient, Color3(0));
    EXPECT_EQ(t.specular, Color3(0));
  }
  // Twice as far, half as bright; a directional light has no distance: full intensity.
  light.position = {0, 0, 8, 1};
  EXPECT_NEAR(evaluateTerms({&light, 1}, lm, m, LightingModel::Wylie, {}).diffuse.r, 2 * 0.5 / 8, kTol);
  light.position = {0, 0, 1, 0};
  EXPECT_NEAR(evaluateTerms({&light, 1}, lm, m, LightingModel::Wylie, {}).diffuse.r, 1, kTol);
}

// Bouknight (1970): I = I_a·k_a + I_l·k_d·cos θ, no distance, no spot, no highlight.
TEST(Bouknight, AmbientPlusLambertWithoutAttenuation) {
  EyeLight light;
  light.position = {0, 0, 2, 1};
  light.attenuation = {0, 0, 1};  // 1/d² under GL; not in 1970
  light.ambient = Color3(1);      // GL's per-light ambient is not Bouknight's either
  Material m;
  m.ambient = {0.4f, 0.4f, 0.4f, 1};
  m.diffuse = {0.5f, 0.5f, 0.5f, 1};
  m.specular = {1, 1, 1, 1};
  m.shininess = 1;
  LightModel lm;
  lm.ambient = Color3(0.25f);
  const LightingTerms t =
      evaluateTerms({&light, 1}, lm, m, LightingModel::Bouknight, {Vec3(0), dirAt(60), Vec3(0, 0, 1)});
  EXPECT_NEAR(t.ambient.r, 0.25 * 0.4, kTol);
  EXPECT_NEAR(t.diffuse.r, 0.5 * 0.5, kTol);  // cos 60°
  EXPECT_EQ(t.specular, Color3(0));
  // Facing away: the ambient alone.
  const LightingTerms away =
      evaluateTerms({&light, 1}, lm, m, LightingModel::Bouknight, {Vec3(0), Vec3(0, 0, -1), Vec3(0, 0, 1)});
  EXPECT_EQ(away.diffuse, Color3(0));
}

TEST(Models, EveryNameParsesBack) {
  for (LightingModel m : kLightingModels) EXPECT_EQ(parseLightingModel(toString(m)), m);
  EXPECT_EQ(lightingModelNames(), "blinn-phong, phong, lambert, cook-torrance, wylie or bouknight");
}

}  // namespace
}  // namespace illum
