// `illum eval`: the lighting equation at one surface point for one light, as a table of terms,
// the way a textbook exercise is solved by hand.
#include <illum/error.h>
#include <illum/lighting.h>

#include "cli_values.h"
#include "commands.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

namespace illum::cli {
namespace {

struct EvalOptions {
  std::string model = "blinn-phong";
  std::string lightAmbient, lightDiffuse, lightSpecular;
  std::string materialAmbient, materialDiffuse, materialSpecular, materialEmission;
  std::string shininess, globalAmbient, distance, attenuation;
  std::string angleNL, angleRV, angleNH;
  std::string normal, toLight, toViewer;
  bool json = false;
};

struct Geometry {
  Vec3 N, L, V;
};

Vec3 unitVector(const std::string& option, const std::string& text) {
  const Vec3 v = parseVec3(option, text);
  const Real len = glm::length(v);
  if (!(len > 0) || !std::isfinite(len)) throw InputError(option + ": expected a non-zero vector, got \"" + text + "\"");
  return v / len;
}

// The geometry from angles: N = +Z, L in the XZ plane θ from N, and a viewer placed so that the
// requested specular angle holds.
Geometry geometryFromAngles(const EvalOptions& o, LightingModel model) {
  const Real theta = o.angleNL.empty() ? Real(0) : parseNumber("--angle-nl", o.angleNL, 0, 180);
  const Real t = glm::radians(theta);
  Geometry g{Vec3(0, 0, 1), Vec3(std::sin(t), 0, std::cos(t)), Vec3(0, 0, 1)};
  if (model == LightingModel::Phong) {
    const Real phi = glm::radians(o.angleRV.empty() ? Real(0) : parseNumber("--angle-rv", o.angleRV, 0, 180));
    // R is L mirrored about N; V turns φ away from R, out of the plane of incidence.
    const Vec3 R(-std::sin(t), 0, std::cos(t));
    g.V = std::cos(phi) * R + std::sin(phi) * Vec3(0, 1, 0);
  } else if (model == LightingModel::BlinnPhong) {
    const Real psiDeg = o.angleNH.empty() ? Real(0) : parseNumber("--angle-nh", o.angleNH, 0, 180);
    const Real psi = glm::radians(psiDeg);
    // H sits ψ from N in the plane of incidence; V is L mirrored about H, so H = normalize(L + V).
    const Vec3 H(std::sin(psi), 0, std::cos(psi));
    const Real HoL = glm::dot(H, g.L);
    if (theta < 90 && !(HoL > Real(1e-6)))
      throw InputError("--angle-nh: no viewer gives an angle of " + o.angleNH + "° between N and H when L is " +
                       (o.angleNL.empty() ? std::string("0") : o.angleNL) +
                       "° from N: the halfway vector always lies within 90° of L");
    g.V = HoL > 0 ? glm::normalize(Real(2) * HoL * H - g.L) : Vec3(0, 0, 1);
  }
  return g;
}

Geometry geometry(const EvalOptions& o, LightingModel model) {
  const bool vectors = !o.normal.empty() || !o.toLight.empty() || !o.toViewer.empty();
  const bool angles = !o.angleNL.empty() || !o.angleRV.empty() || !o.angleNH.empty();
  if (vectors && angles)
    throw InputError("give the geometry either as angles (--angle-nl, --angle-rv, --angle-nh) or as vectors "
                     "(--normal, --to-light, --to-viewer), not both");
  if (model != LightingModel::Phong && !o.angleRV.empty())
    throw InputError("--angle-rv: R·V is the phong model's specular angle; use --model phong, or --angle-nh for blinn-phong");
  if (model != LightingModel::BlinnPhong && !o.angleNH.empty())
    throw InputError("--angle-nh: N·H is the blinn-phong model's specular angle; use --model blinn-phong, or --angle-rv for phong");
  if (!vectors) return geometryFromAngles(o, model);
  return {o.normal.empty() ? Vec3(0, 0, 1) : unitVector("--normal", o.normal),
          o.toLight.empty() ? Vec3(0, 0, 1) : unitVector("--to-light", o.toLight),
          o.toViewer.empty() ? Vec3(0, 0, 1) : unitVector("--to-viewer", o.toViewer)};
}

Color4 color4(const std::string& option, const std::string& text, Color4 fallback) {
  return text.empty() ? fallback : Color4(parseColor(option, text, false), 1);
}

Color3 color3(const std::string& option, const std::string& text, Color3 fallback) {
  return text.empty() ? fallback : parseColor(option, text, false);
}

void printRow(const char* name, const Color3& c) {
  std::printf("%-10s %9.4f %9.4f %9.4f\n", name, double(c.r), double(c.g), double(c.b));
}

// A JSON array of three numbers at the precision they were computed in (6 significant digits
// for float, 15 for double), not the binary expansion of a float.
std::string triple(const Color3& c) {
  const int digits = std::numeric_limits<Real>::digits10;
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.*g,%.*g,%.*g]", digits, double(c.r), digits, double(c.g), digits, double(c.b));
  return buf;
}

int runEval(const EvalOptions& o) {
  const auto model = parseLightingModel(o.model);
  if (!model) throw InputError("--model: expected blinn-phong, phong or lambert, got \"" + o.model + "\"");

  // Light and material: the scene format's defaults for whatever is not given.
  const Light defaults;
  const Material materialDefaults;
  EyeLight light;
  light.ambient = color3("--light-ambient", o.lightAmbient, defaults.ambient);
  light.diffuse = color3("--light-diffuse", o.lightDiffuse, defaults.diffuse);
  light.specular = color3("--light-specular", o.lightSpecular, defaults.specular);
  Material material;
  material.ambient = color4("--material-ambient", o.materialAmbient, materialDefaults.ambient);
  material.diffuse = color4("--material-diffuse", o.materialDiffuse, materialDefaults.diffuse);
  material.specular = color4("--material-specular", o.materialSpecular, materialDefaults.specular);
  material.emission = color4("--material-emission", o.materialEmission, materialDefaults.emission);
  if (!o.shininess.empty()) material.shininess = parseNumber("--shininess", o.shininess, 0, Real(1e6));
  LightModel lightModel;
  lightModel.ambient = color3("--global-ambient", o.globalAmbient, Color3(0));

  const Geometry g = geometry(o, *model);
  SurfaceGeometry surface{Vec3(0), g.N, g.V};
  if (o.distance.empty()) {
    if (!o.attenuation.empty()) throw InputError("--attenuation: needs --distance (a directional light is never attenuated)");
    light.position = Vec4(g.L, 0);
  } else {
    const Real d = parseNumber("--distance", o.distance, 0, Real(1e30));
    if (!(d > 0)) throw InputError("--distance: expected a positive distance, got " + o.distance);
    light.position = Vec4(d * g.L, 1);
    if (!o.attenuation.empty()) {
      const Vec3 k = parseVec3("--attenuation", o.attenuation);
      if (k.x < 0 || k.y < 0 || k.z < 0 || k == Vec3(0))
        throw InputError("--attenuation: expected a,b,c ≥ 0, not all zero, got \"" + o.attenuation + "\"");
      light.attenuation = k;
    }
  }

  const LightingTerms terms = evaluateTerms({&light, 1}, lightModel, material, *model, surface);
  const Color3 total = Color3(clampedColor(terms, material));
  if (o.json) {
    std::cout << "{\"emission\":" << triple(terms.emission) << ",\"ambient\":" << triple(terms.ambient)
              << ",\"diffuse\":" << triple(terms.diffuse) << ",\"specular\":" << triple(terms.specular)
              << ",\"total\":" << triple(total) << "}\n";
    return 0;
  }
  std::printf("%-10s %9s %9s %9s\n", "", "R", "G", "B");
  printRow("Emission", terms.emission);
  printRow("Ambient", terms.ambient);
  printRow("Diffuse", terms.diffuse);
  printRow("Specular", terms.specular);
  printRow("Total", total);
  const Color3 sum = terms.sum();
  if (sum != total)
    std::printf("(Total is clamped to [0,1] per channel; the unclamped sum is %.4f %.4f %.4f)\n",
                double(sum.r), double(sum.g), double(sum.b));
  std::printf("model %s; N·L = %.4f; N = (%.4f, %.4f, %.4f), L = (%.4f, %.4f, %.4f), V = (%.4f, %.4f, %.4f)\n",
              std::string(toString(*model)).c_str(), double(glm::dot(g.N, g.L)), double(g.N.x), double(g.N.y),
              double(g.N.z), double(g.L.x), double(g.L.y), double(g.L.z), double(g.V.x), double(g.V.y), double(g.V.z));
  return 0;
}

}  // namespace

Command addEvalCommand(CLI::App& app) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval", "Evaluate the lighting equation at one surface point for one light and print its terms");
  cmd->footer(
      "Example (the 'Colored light' exercise of the seed lecture notes):\n"
      "  illum eval --model phong --distance 1 --angle-nl 30 --angle-rv 0 \\\n"
      "    --light-ambient 0.4,0.9,0.2 --light-diffuse 0.3,1,1 --light-specular 1,1,1 \\\n"
      "    --material-ambient 0.9,0.9,0.1 --material-diffuse 0.8,1,0.8 --material-specular 0,1,0.6 --shininess 2\n"
      "Colours are R,G,B (each ≥ 0) or #rrggbb (bytes / 255).");
  cmd->add_option("--model", o->model, "Lighting model: blinn-phong, phong or lambert")->capture_default_str();
  cmd->add_option("--light-ambient", o->lightAmbient, "Light ambient colour R,G,B [0,0,0]");
  cmd->add_option("--light-diffuse", o->lightDiffuse, "Light diffuse colour R,G,B [1,1,1]");
  cmd->add_option("--light-specular", o->lightSpecular, "Light specular colour R,G,B [1,1,1]");
  cmd->add_option("--material-ambient", o->materialAmbient, "Material ambient R,G,B [0.2,0.2,0.2]");
  cmd->add_option("--material-diffuse", o->materialDiffuse, "Material diffuse R,G,B [0.8,0.8,0.8]");
  cmd->add_option("--material-specular", o->materialSpecular, "Material specular R,G,B [0,0,0]");
  cmd->add_option("--material-emission", o->materialEmission, "Material emission R,G,B [0,0,0]");
  cmd->add_option("--shininess", o->shininess, "Specular exponent n [0]");
  cmd->add_option("--global-ambient", o->globalAmbient, "Light-model (global) ambient R,G,B [0,0,0]");
  cmd->add_option("--distance", o->distance, "Distance D to a positional light (default: a directional light)");
  cmd->add_option("--attenuation", o->attenuation, "Attenuation a,b,c of 1/(a+bD+cD²) [1,0,0]");
  cmd->add_option("--angle-nl", o->angleNL, "Angle between N and L, degrees [0]");
  cmd->add_option("--angle-rv", o->angleRV, "Angle between R and V, degrees (phong) [0]");
  cmd->add_option("--angle-nh", o->angleNH, "Angle between N and H, degrees (blinn-phong) [0]");
  cmd->add_option("--normal", o->normal, "Surface normal x,y,z (normalized) [0,0,1]");
  cmd->add_option("--to-light", o->toLight, "Direction to the light x,y,z (normalized) [0,0,1]");
  cmd->add_option("--to-viewer", o->toViewer, "Direction to the viewer x,y,z (normalized) [0,0,1]");
  cmd->add_flag("--json", o->json, "Print the terms as JSON (terms unclamped, total clamped)");
  return [o] { return runEval(*o); };
}

}  // namespace illum::cli
