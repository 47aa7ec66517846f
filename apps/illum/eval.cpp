// `illum eval`: the lighting equation at one surface point for one light, as a table of terms,
// the way a textbook exercise is solved by hand.
#include <illum/captions.h>
#include <illum/error.h>
#include <illum/lighting.h>

#include "cli_values.h"
#include "commands.h"
#include "eval.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <cstdio>
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <sstream>

namespace illum::cli {
namespace {

struct Geometry {
  Vec3 N, L, V;
};

Vec3 unitVector(const std::string& option, const std::string& text) {
  const Vec3 v = parseVec3(option, text);
  const Real len = glm::length(v);
  if (!(len > 0) || !std::isfinite(len)) throw InputError(option + ": expected a non-zero vector, got \"" + text + "\"");
  return v / len;
}

// The geometry from angles. Everything lies in one plane, the plane of incidence (XZ), for every
// model, so that phong and blinn-phong can be compared on the same geometry: N = +Z, L at θ from N
// towards +X, and V at the signed angle α from N (positive towards L's side). The specular angle
// asked for fixes α: phong's φ = ∠(R, V) with R at −θ gives α = φ − θ; blinn-phong's ψ = ∠(N, H)
// with H = normalize(L + V) halfway between them gives α = 2ψ − θ (or −2ψ − θ, H on the other
// side). A viewer below the surface (|α| > 90°) does not exist: such input is refused.
Geometry geometryFromAngles(const EvalOptions& o, LightingModel model) {
  const Real theta = o.angleNL.empty() ? Real(0) : parseNumber("--angle-nl", o.angleNL, 0, 180);
  const auto inPlane = [](Real degrees) {
    const Real r = glm::radians(degrees);
    return Vec3(std::sin(r), 0, std::cos(r));
  };
  Geometry g{Vec3(0, 0, 1), inPlane(theta), Vec3(0, 0, 1)};
  const auto above = [](Real alpha) { return alpha >= -90 && alpha <= 90; };
  const std::string lightText = (o.angleNL.empty() ? std::string("0") : o.angleNL) + "° from N";
  if (model == LightingModel::Phong && !o.angleRV.empty()) {
    const Real phi = parseNumber("--angle-rv", o.angleRV, 0, 180);
    const Real alpha = phi - theta;
    if (!above(alpha))
      throw InputError("--angle-rv: no viewer above the surface makes an angle of " + o.angleRV + "° with R when L is " +
                       lightText + " (V in the plane of incidence: the angle must lie between " +
                       std::to_string(int(std::max<Real>(0, theta - 90))) + "° and " +
                       std::to_string(int(std::min<Real>(180, theta + 90))) + "°)");
    g.V = inPlane(alpha);
  } else if ((model == LightingModel::BlinnPhong || model == LightingModel::CookTorrance) && !o.angleNH.empty()) {
    const Real psi = parseNumber("--angle-nh", o.angleNH, 0, 180);
    if (above(2 * psi - theta)) g.V = inPlane(2 * psi - theta);
    else if (above(-2 * psi - theta)) g.V = inPlane(-2 * psi - theta);
    else
      throw InputError("--angle-nh: no viewer above the surface gives an angle of " + o.angleNH +
                       "° between N and H when L is " + lightText +
                       " (H lies halfway between L and V, so the angle must lie between " +
                       std::to_string(int(std::max<Real>(0, (theta - 90) / 2))) + "° and " +
                       std::to_string(int((theta + 90) / 2)) + "°)");
    if (glm::length(g.L + g.V) < Real(1e-6))
      throw InputError("--angle-nh: with L " + lightText + " that viewer looks straight back along −L, where the "
                       "halfway vector H = normalize(L + V) is undefined");
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
  if (model != LightingModel::BlinnPhong && model != LightingModel::CookTorrance && !o.angleNH.empty())
    throw InputError("--angle-nh: N·H is the specular angle of blinn-phong and cook-torrance; use one of them, or "
                     "--angle-rv for phong");
  if (!vectors) return geometryFromAngles(o, model);
  return {o.normal.empty() ? Vec3(0, 0, 1) : unitVector("--normal", o.normal),
          o.toLight.empty() ? Vec3(0, 0, 1) : unitVector("--to-light", o.toLight),
          o.toViewer.empty() ? Vec3(0, 0, 1) : unitVector("--to-viewer", o.toViewer)};
}

// Material colours are reflectances in [0,1]; light colours intensities ≥ 0 (docs/cli.md).
Color4 color4(const std::string& option, const std::string& text, Color4 fallback) {
  return text.empty() ? fallback : Color4(parseColor(option, text, true), 1);
}

Color3 color3(const std::string& option, const std::string& text, Color3 fallback) {
  return text.empty() ? fallback : parseColor(option, text, false);
}

std::string vec(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4f, %.4f, %.4f)", double(v.x), double(v.y), double(v.z));
  return buf;
}

// A JSON number; JSON has no infinity or NaN, so those (which validation keeps out) become null.
std::string number(Real x) {
  if (!std::isfinite(x)) return "null";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", std::numeric_limits<Real>::digits10, double(x));
  return buf;
}

void printRow(const char* name, const Color3& c) {
  std::printf("%-10s %9.4f %9.4f %9.4f\n", name, double(c.r), double(c.g), double(c.b));
}

// A JSON array of three numbers at the precision they were computed in (6 significant digits
// for float, 15 for double), not the binary expansion of a float.
std::string triple(const Color3& c) { return "[" + number(c.r) + "," + number(c.g) + "," + number(c.b) + "]"; }

// The factors' formulas with their numbers, and why a term is zero where it is: what a student
// would work out by hand next to the figures above.
void explainFactors(const EyeLight& light, const Material& material, LightingModel model, const LightDetail& d) {
  if (d.positional) {
    const Vec3& k = light.attenuation;
    const double dist = double(d.distance);
    std::printf("attenuation = 1/(k_c + k_l·d + k_q·d²) = 1/(%g + %g·%.4f + %g·%.4f²) = %.4f\n", double(k.x), double(k.y),
                dist, double(k.z), dist, double(d.attenuation));
  }
  if (light.isSpot()) {
    const double cosAngle = double(glm::dot(-d.L, glm::normalize(light.spotDirection)));
    const double angle = glm::degrees(std::acos(std::clamp(cosAngle, -1.0, 1.0)));
    if (cosAngle < double(light.spotCosCutoff))
      std::printf("spot: the point is %.2f° off the spot's axis, outside its cutoff of %g°: spot factor 0, the light "
                  "adds nothing\n",
                  angle, double(light.spotCutoff));
    else
      std::printf("spot: the point is %.2f° off the spot's axis, inside its cutoff of %g°: factor cos(%.2f°)^%g = %.4f\n",
                  angle, double(light.spotCutoff), angle, double(light.spotExponent), double(d.spot));
  }
  if (!(d.NoL > 0)) {
    std::printf("diffuse and specular are 0: the light is behind the surface (N·L = %.4f ≤ 0), and GL adds a light's "
                "diffuse and specular terms only where N·L > 0",
                double(d.NoL));
    const double base = model == LightingModel::BlinnPhong ? double(d.NoH) : model == LightingModel::Phong ? double(d.RoV) : -1;
    if (base > 0 && model != LightingModel::CookTorrance)
      std::printf(" (%s^%g would be %.4f)", model == LightingModel::BlinnPhong ? "(N·H)" : "(R·V)",
                  double(material.shininess), std::pow(base, double(material.shininess)));
    std::printf("\n");
  } else if ((model == LightingModel::BlinnPhong && !(d.NoH > 0)) || (model == LightingModel::Phong && !(d.RoV > 0))) {
    std::printf("specular is 0: %s ≤ 0, the highlight's lobe points away from the viewer\n",
                model == LightingModel::BlinnPhong ? "N·H" : "R·V");
  }
}

// The terms at the same point as a lecture note computes them (--convention), by the same code the
// renderer follows the note with.
struct NoteTerms {
  Convention convention;
  LightingTerms terms;
  LightDetail d;
  Color3 total;
};

// One evaluation: everything the report prints.
struct Evaluation {
  LightingModel model;
  Geometry g;
  EyeLight light;
  Material material;
  LightingTerms terms;
  LightDetail d;
  Color3 total;
  std::optional<NoteTerms> note;  // --convention: the note's terms at the same point
};

Evaluation evaluate(const EvalOptions& o) {
  const auto model = parseLightingModel(o.model);
  if (!model) badChoice("--model", o.model, lightingModelChoices());

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
  if (!o.baseColor.empty() || !o.metallic.empty() || !o.roughness.empty() || !o.f0.empty() || !o.distribution.empty()) {
    // A physically based material, as a scene file's base_color, metallic, roughness, f0.
    if (!o.materialAmbient.empty() || !o.materialDiffuse.empty() || !o.materialSpecular.empty() || !o.shininess.empty())
      throw InputError("--base-color, --metallic, --roughness, --f0 make a physically based material: give them or "
                       "--material-ambient, --material-diffuse, --material-specular, --shininess, not both");
    PhysicalMaterial p;
    p.baseColor = Color3(color4("--base-color", o.baseColor, Color4(p.baseColor, 1)));
    if (!o.metallic.empty()) p.metallic = parseNumber("--metallic", o.metallic, 0, 1);
    if (!o.roughness.empty()) p.roughness = parseNumber("--roughness", o.roughness, 0, 1);
    p.f0 = Color3(color4("--f0", o.f0, Color4(p.f0, 1)));
    if (o.distribution == "beckmann") p.distribution = Microfacet::Beckmann;
    else if (!o.distribution.empty() && o.distribution != "ggx")
      badChoice("--distribution", o.distribution, {"ggx", "beckmann"});
    glFromPhysical(material, p);
  }
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

  // The spot: its axis (default: from the light straight at the point), exponent and cutoff.
  if (!o.spotCutoff.empty()) {
    const Real cutoff = parseNumber("--spot-cutoff", o.spotCutoff, 0, 180);
    if (cutoff > 90 && cutoff != 180)
      throw InputError("--spot-cutoff: expected degrees in [0, 90], or 180 for no cone (as glLight), got " + o.spotCutoff);
    light.spotCutoff = cutoff;
    light.spotCosCutoff = cutoff == 180 ? Real(-2) : std::cos(glm::radians(cutoff));
  }
  light.spotDirection = o.spotDirection.empty() ? -g.L : unitVector("--spot-direction", o.spotDirection);
  if (!o.spotExponent.empty()) light.spotExponent = parseNumber("--spot-exponent", o.spotExponent, 0, 128);
  if ((!o.spotDirection.empty() || !o.spotExponent.empty()) && o.spotCutoff.empty())
    throw InputError(std::string(o.spotDirection.empty() ? "--spot-exponent" : "--spot-direction") +
                     ": a spot needs --spot-cutoff (without it the light has no cone)");

  // The same accumulateLight the renderer uses, recording every intermediate.
  LightingTerms terms = evaluateTerms({}, lightModel, material, *model, surface);  // emission, global ambient
  LightDetail d;
  accumulateLight(terms, light, material, *model, surface, &d);
  const Color3 total = Color3(clampedColor(terms, material));
  std::optional<NoteTerms> note;
  if (!o.convention.empty()) {
    const std::optional<Convention> c = parseConvention(o.convention);
    if (!c) badChoice("--convention", o.convention, conventionChoices());
    LightModel noteModel = lightModel;
    noteModel.convention = *c;
    NoteTerms& n = note.emplace(NoteTerms{*c, evaluateTerms({}, noteModel, material, *model, surface), {}, {}});
    accumulateLight(n.terms, light, material, *model, surface, &n.d, *c);
    n.total = Color3(clampedColor(n.terms, material));
  }
  return {*model, g, light, material, terms, d, total, note};
}

// The report as one JSON object: the terms unclamped, the total clamped, the vectors and factors.
std::string evaluationJson(const Evaluation& e) {
  const auto& [model, g, light, material, terms, d, total, note] = e;
  std::ostringstream json;
    json << "{\"emission\":" << triple(terms.emission) << ",\"ambient\":" << triple(terms.ambient)
            << ",\"diffuse\":" << triple(terms.diffuse) << ",\"specular\":" << triple(terms.specular)
            << ",\"total\":" << triple(total) << ",\"N\":" << triple(g.N) << ",\"L\":" << triple(d.L)
            << ",\"V\":" << triple(g.V) << ",\"NoL\":" << number(d.NoL);
  if (model == LightingModel::BlinnPhong)
    json << ",\"H\":" << triple(d.H) << ",\"NoH\":" << number(d.NoH) << ",\"lobe\":" << number(d.lobe);
  if (model == LightingModel::CookTorrance)
    json << ",\"H\":" << triple(d.H) << ",\"NoH\":" << number(d.NoH) << ",\"NoV\":" << number(d.NoV)
              << ",\"VoH\":" << number(d.VoH) << ",\"D\":" << number(d.D) << ",\"Vis\":" << number(d.visibility)
              << ",\"F\":" << triple(d.F);
  if (model == LightingModel::Phong)
    json << ",\"R\":" << triple(d.R) << ",\"RoV\":" << number(d.RoV) << ",\"lobe\":" << number(d.lobe);
  json << ",\"attenuation\":" << number(d.attenuation) << ",\"spot\":" << number(d.spot);
  if (note) {
    const LightingTerms& t = note->terms;
    json << ",\"convention\":{\"name\":\"" << toString(note->convention) << "\",\"emission\":" << triple(t.emission)
         << ",\"ambient\":" << triple(t.ambient) << ",\"diffuse\":" << triple(t.diffuse)
         << ",\"specular\":" << triple(t.specular) << ",\"total\":" << triple(note->total);
    if (model == LightingModel::BlinnPhong) json << ",\"NoH\":" << number(note->d.NoH);
    json << "}";
  }
  json << "}";
  return json.str();
}

int printEvaluation(const EvalOptions& o, const Evaluation& e) {
  const auto& [model, g, light, material, terms, d, total, note] = e;
  if (o.json) {
    std::cout << evaluationJson(e) << "\n";
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
  std::printf("model %s; N = %s, L = %s, V = %s\n", std::string(toString(model)).c_str(), vec(g.N).c_str(),
              vec(d.L).c_str(), vec(g.V).c_str());
  std::printf("N·L = %.4f", double(d.NoL));
  if (model == LightingModel::BlinnPhong)
    std::printf("; H = %s, N·H = %.4f, (N·H)^%g = %.4f", vec(d.H).c_str(), double(d.NoH), double(material.shininess),
                double(d.lobe));
  if (model == LightingModel::Phong)
    std::printf("; R = %s, R·V = %.4f, (R·V)^%g = %.4f", vec(d.R).c_str(), double(d.RoV), double(material.shininess),
                double(d.lobe));
  if (model == LightingModel::CookTorrance)
    std::printf("; H = %s, N·H = %.4f, N·V = %.4f, V·H = %.4f\nD = %.4f, V = G/(4 N·L N·V) = %.4f, F = %s",
                vec(d.H).c_str(), double(d.NoH), double(d.NoV), double(d.VoH), double(d.D), double(d.visibility),
                vec(d.F).c_str());
  std::printf("\nattenuation %.4f%s; spot factor %.4f%s\n", double(d.attenuation),
              d.positional ? "" : " (directional light)", double(d.spot), light.isSpot() ? "" : " (no cone)");
  explainFactors(light, material, model, d);
  if (note) {
    std::printf("\nconvention %s (%s):\n", std::string(toString(note->convention)).c_str(),
                describeConvention(note->convention).c_str());
    if (note->convention == Convention::NoteWorldSpace)
      std::printf("(the same at one point whose V is given: world space changes V across a surface, from each point "
                  "to the camera rather than (0, 0, 1); see it with illum render --convention note-world-space)\n");
    else if (!follows(model, note->convention))
      std::printf("(the %s model is the same under it: the note's convention changes blinn-phong, phong and lambert)\n",
                  std::string(toString(model)).c_str());
    std::printf("%-10s %9s %9s %9s   %s\n", "", "R", "G", "B", "against GL's");
    const auto compared = [](const char* name, const Color3& c, const Color3& gl) {
      std::printf("%-10s %9.4f %9.4f %9.4f   %+.4f %+.4f %+.4f\n", name, double(c.r), double(c.g), double(c.b),
                  double(c.r - gl.r), double(c.g - gl.g), double(c.b - gl.b));
    };
    compared("Emission", note->terms.emission, terms.emission);
    compared("Ambient", note->terms.ambient, terms.ambient);
    compared("Diffuse", note->terms.diffuse, terms.diffuse);
    compared("Specular", note->terms.specular, terms.specular);
    compared("Total", note->total, total);
    if (note->convention == Convention::NoteHalfSum && model == LightingModel::BlinnPhong)
      std::printf("N·H with H = (L + V)/2: %.4f (GL's, normalised: %.4f)\n", double(note->d.NoH), double(d.NoH));
  }
  return 0;
}

// The options a sweep may vary, by name, and where their text is.
struct SweepOption {
  const char* name;
  std::string EvalOptions::*text;
};
constexpr SweepOption kSweepable[] = {{"--angle-nl", &EvalOptions::angleNL}, {"--angle-rv", &EvalOptions::angleRV},
                                      {"--angle-nh", &EvalOptions::angleNH}, {"--distance", &EvalOptions::distance},
                                      {"--shininess", &EvalOptions::shininess}};
constexpr std::size_t kMostSweepValues = 1000;

// A sweep's values: "from:to:step" (to included, within rounding) or "a,b,c"; one number is no sweep.
std::vector<std::string> sweepValues(const std::string& option, const std::string& text) {
  std::vector<std::string> values;
  if (text.find(':') != std::string::npos) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
    if (parts.size() != 3) throw InputError(option + ": expected a sweep from:to:step, got \"" + text + "\"");
    const Real from = parseNumber(option, parts[0], Real(-1e30), Real(1e30)), to = parseNumber(option, parts[1], Real(-1e30), Real(1e30));
    const Real step = parseNumber(option, parts[2], Real(0), Real(1e30));
    if (!(step > 0) || to < from) throw InputError(option + ": expected from ≤ to and a positive step, got \"" + text + "\"");
    const double count = std::floor(double(to - from) / double(step) + 1e-9) + 1;
    if (count > double(kMostSweepValues))
      throw InputError(option + ": " + text + " is " + std::to_string(std::llround(count)) + " values; expected at most " +
                       std::to_string(kMostSweepValues));
    for (long i = 0; i < long(count); ++i) values.push_back(number(from + Real(i) * step));
  } else {
    std::stringstream in(text);
    for (std::string value; std::getline(in, value, ',');) values.push_back(value);
    if (values.size() > kMostSweepValues)
      throw InputError(option + ": " + std::to_string(values.size()) + " values; expected at most " + std::to_string(kMostSweepValues));
  }
  return values;
}

// The option a sweep varies (one of --angle-nl, ..., given as from:to:step or a list), or none.
const SweepOption* sweptOption(const EvalOptions& o) {
  const SweepOption* swept = nullptr;
  for (const SweepOption& s : kSweepable)
    if ((o.*s.text).find_first_of(",:") != std::string::npos) {
      if (swept) throw InputError(std::string(swept->name) + " and " + s.name + ": a sweep varies one of them at a time");
      swept = &s;
    }
  return swept;
}

int runEval(const EvalOptions& o) {
  if (!o.plot.empty()) checkEvalPlot(o.plot);
  const SweepOption* swept = sweptOption(o);
  if (!o.plot.empty()) writeEvalPlot(o, o.plot);
  if (o.quiet) {
    evalJson(o);  // checked all the same
    return 0;
  }
  if (o.json) {
    std::cout << evalJson(o) << "\n";
    return 0;
  }
  if (!swept) return printEvaluation(o, evaluate(o));
  // The terms against the swept value, a row each.
  const std::vector<std::string> values = sweepValues(swept->name, o.*swept->text);
  std::printf("%-12s | %-20s | %-20s | %-20s | %-20s | %-20s\n", swept->name + 2, "emission R G B", "ambient R G B",
              "diffuse R G B", "specular R G B", "total R G B");
  for (const std::string& value : values) {
    EvalOptions at = o;
    at.*swept->text = value;
    const Evaluation e = evaluate(at);
    const auto cell = [](const Color3& c) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.4f %.4f %.4f", double(c.r), double(c.g), double(c.b));
      return std::string(buf);
    };
    std::printf("%-12s | %-20s | %-20s | %-20s | %-20s | %-20s\n", value.c_str(), cell(e.terms.emission).c_str(),
                cell(e.terms.ambient).c_str(), cell(e.terms.diffuse).c_str(), cell(e.terms.specular).c_str(),
                cell(e.total).c_str());
  }
  return 0;
}

}  // namespace

std::string sweptOptionName(const EvalOptions& o) {
  const SweepOption* swept = sweptOption(o);
  return swept ? std::string(swept->name + 2) : std::string();
}

std::string evalJson(const EvalOptions& o) {
  const SweepOption* swept = sweptOption(o);
  if (!swept) return evaluationJson(evaluate(o));
  // A sweep: an array of the single reports, each with the swept value first.
  std::string json = "[";
  for (const std::string& value : sweepValues(swept->name, o.*swept->text)) {
    EvalOptions at = o;
    at.*swept->text = value;
    json += (json.size() > 1 ? ",{\"" : "{\"") + std::string(swept->name + 2) + "\":" + value + "," +
            evaluationJson(evaluate(at)).substr(1);
  }
  return json + "]";
}

Command addEvalCommand(CLI::App& app) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* cmd = app.add_subcommand(
      "eval", "Evaluate the lighting equation at one surface point for one light and print its terms");
  addEvalOptions(*cmd, *o);
  return [o] { return runEval(*o); };
}

void addEvalOptions(CLI::App& cmd_, EvalOptions& options) {
  CLI::App* cmd = &cmd_;
  EvalOptions* o = &options;
  cmd->footer(
      "Example (the 'Colored light' exercise of the seed lecture notes):\n"
      "  illum eval --model phong --distance 1 --angle-nl 30 --angle-rv 0 \\\n"
      "    --light-ambient 0.4,0.9,0.2 --light-diffuse 0.3,1,1 --light-specular 1,1,1 \\\n"
      "    --material-ambient 0.9,0.9,0.1 --material-diffuse 0.8,1,0.8 --material-specular 0,1,0.6 --shininess 2\n"
      "Colours are R,G,B or #rrggbb (bytes / 255): material colours in [0,1], light colours ≥ 0.");
  cmd->add_option("--model", o->model, "Lighting model: " + lightingModelNames())->capture_default_str();
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
  cmd->add_option("--spot-cutoff", o->spotCutoff, "Spot cone half-angle in degrees, [0, 90] or 180 (no cone) [180]");
  cmd->add_option("--spot-exponent", o->spotExponent, "Spot exponent in [0, 128] [0]");
  cmd->add_option("--spot-direction", o->spotDirection, "Spot axis x,y,z [from the light towards the point]");
  cmd->add_option("--base-color", o->baseColor, "cook-torrance: base colour R,G,B (a physically based material) [0.8,0.8,0.8]");
  cmd->add_option("--metallic", o->metallic, "cook-torrance: metallic, 0..1 [0]");
  cmd->add_option("--roughness", o->roughness, "cook-torrance: perceptual roughness, 0..1 (α = roughness²) [1]");
  cmd->add_option("--f0", o->f0, "cook-torrance: a dielectric's reflectance at normal incidence R,G,B [0.04,0.04,0.04]");
  cmd->add_option("--distribution", o->distribution, "cook-torrance: ggx or beckmann [ggx]");
  cmd->add_flag("--json", o->json, "Print the terms as JSON (terms unclamped, total clamped)");
  cmd->add_option("--plot", o->plot,
                  "Also draw FILE.png: each term against the swept value (with a sweep) and the specular lobes of "
                  "Phong and Blinn-Phong for the light's angle and the shininess");
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing (with --plot: only the figure)");
  cmd->add_option("--convention", o->convention,
                  "Also compute the terms as a lecture note does, beside GL's and against them: note-shader (seed "
                  "001's shader: specular scaled by N·L too, the ambient the material's) or note-half-sum (H = (L+V)/2, "
                  "not normalised)");
}

}  // namespace illum::cli
