#include "sheet_axes.h"

#include <illum/error.h>

#include "cli_values.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace illum::cli {
namespace {

// Axes that are `illum render` options, with their default values.
const std::map<std::string, std::vector<std::string>>& optionAxes() {
  static const std::map<std::string, std::vector<std::string>> axes = {
      {"model", {"lambert", "phong", "blinn-phong", "cook-torrance"}},
      {"shading", {"flat", "gouraud", "phong"}},
      {"convention", {"gl", "note-shader", "note-half-sum", "note-world-space"}},
      {"renderer", {"raster", "whitted", "hall", "path"}},
      {"samples", {"1", "4", "16", "64"}},
      {"max-depth", {"0", "1", "2", "5"}},
      {"tone-map", {"none", "reinhard", "aces"}},
      {"encoding", {"linear", "srgb"}},
      {"environment", {"none", "studio"}},
      {"environment-rotation", {"0", "90", "180", "270"}},
      {"normals", {"flat", "smooth", "auto"}},
      {"crease-angle", {"10", "40", "90"}},
      {"azimuth", {"0", "90", "180", "270"}},
      {"elevation", {"0", "30", "60"}},
      {"zoom", {"0.5", "1", "2"}},
      {"light-intensity", {"0.5", "1", "2"}},
      {"view-angle", {"20", "30", "60"}},
  };
  return axes;
}

std::vector<std::string> splitValues(const std::string& text) {
  const char separator = text.find(';') != std::string::npos ? ';' : ',';
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

// material.KEY: what the key takes.
enum class ValueKind { Colour, Number, UnitNumber };
const std::map<std::string, ValueKind>& materialKeys() {
  static const std::map<std::string, ValueKind> keys = {
      {"ambient", ValueKind::Colour},  {"diffuse", ValueKind::Colour},      {"specular", ValueKind::Colour},
      {"emission", ValueKind::Colour}, {"base_color", ValueKind::Colour},   {"shininess", ValueKind::Number},
      {"metallic", ValueKind::UnitNumber}, {"roughness", ValueKind::UnitNumber}};
  return keys;
}
const std::map<std::string, ValueKind>& lightKeys() {
  static const std::map<std::string, ValueKind> keys = {
      {"ambient", ValueKind::Colour},        {"diffuse", ValueKind::Colour},        {"specular", ValueKind::Colour},
      {"position", ValueKind::Colour},       {"spot_direction", ValueKind::Colour}, {"attenuation", ValueKind::Colour},
      {"spot_exponent", ValueKind::Number},  {"spot_cutoff", ValueKind::Number}};
  return keys;
}

std::string keyList(const std::map<std::string, ValueKind>& keys) {
  std::string list;
  for (const auto& [k, unused] : keys) list += (list.empty() ? "" : ", ") + k;
  return list;
}

// A colour or vector value: three numbers, or one for all three (a grey).
Vec3 threeNumbers(const std::string& option, const std::string& text, bool unitRange) {
  if (text.find(',') == std::string::npos && text.find('#') == std::string::npos) {
    const Real v = parseNumber(option, text, unitRange ? Real(0) : Real(-1e6), unitRange ? Real(1) : Real(1e6));
    return Vec3(v);
  }
  return unitRange ? parseColor(option, text, true) : parseVec3(option, text);
}

// Validates one value of a scene-key axis by applying it to a throwaway scene.
void checkValue(const SheetAxis& axis, const std::string& value, const std::string& option) {
  Scene probe;
  probe.lights.resize(8);
  probe.objects.resize(1);
  try {
    applyToScene(axis, value, probe);
  } catch (const InputError& e) {
    throw InputError(option + ": " + e.what());
  }
}

}  // namespace

SheetAxis parseSheetAxis(const std::string& option, const std::string& spec, std::size_t lightCount) {
  SheetAxis axis;
  const auto eq = spec.find('=');
  axis.name = spec.substr(0, eq);
  if (eq != std::string::npos) axis.values = splitValues(spec.substr(eq + 1));
  const bool material = axis.name.rfind("material.", 0) == 0, light = axis.name.rfind("light.", 0) == 0;
  const auto known = optionAxes().find(axis.name);
  if (known == optionAxes().end() && axis.name != "shininess" && axis.name != "light-count" && !material && !light) {
    std::string names;
    std::vector<std::string> axes = {"shininess", "light-count"};
    for (const auto& [n, unused] : optionAxes()) names += n + ", ", axes.push_back(n);
    const std::optional<std::string> meant = closestName(axis.name, axes);
    throw InputError(option + ": expected an axis (" + names + "shininess, light-count, material.KEY or light.N.KEY), got \"" +
                     axis.name + "\"" + (meant ? "; did you mean " + *meant + "?" : ""));
  }
  if (eq == std::string::npos) {
    if (known != optionAxes().end()) axis.values = known->second;
    else if (axis.name == "shininess") axis.values = {"1", "8", "32", "128"};
    else if (axis.name == "light-count")
      for (std::size_t n = 1; n <= std::min<std::size_t>(lightCount, 8); ++n) axis.values.push_back(std::to_string(n));
    else throw InputError(option + ": " + axis.name + " takes its values: " + axis.name + "=v1;v2;...");
  }
  if (axis.values.empty() || std::any_of(axis.values.begin(), axis.values.end(), [](const std::string& v) { return v.empty(); }))
    throw InputError(option + ": expected values after " + axis.name + "=, separated by commas (or by ';' when they hold commas)");
  if (axis.values.size() > 16) throw InputError(option + ": at most 16 values on an axis, got " + std::to_string(axis.values.size()));
  // Enumerations and numbers are checked now, so that no picture is rendered before an error.
  for (const std::string& v : axis.values) {
    const std::string what = option + " " + axis.name;
    if (axis.name == "model" && !parseLightingModel(v)) badChoice(what, v, lightingModelChoices());
    if (axis.name == "shading" && !parseShading(v)) badChoice(what, v, {"flat", "gouraud", "phong"});
    if (axis.name == "convention" && !parseConvention(v)) badChoice(what, v, conventionChoices());
    if (axis.name == "renderer" && !parseRendererKind(v)) badChoice(what, v, {"raster", "whitted", "hall", "path"});
    if (axis.name == "tone-map" && !parseToneMap(v)) badChoice(what, v, {"none", "reinhard", "aces"});
    if (axis.name == "encoding" && !parseEncoding(v)) badChoice(what, v, {"linear", "srgb"});
    if (axis.name == "normals" && v != "auto" && v != "flat" && v != "smooth" && v != "file")
      throw InputError(what + ": expected auto, flat, smooth or file, got \"" + v + "\"");
    if (axis.name == "samples") parseInteger(what, v, 1, kMaxSamples);
    if (axis.name == "max-depth") parseInteger(what, v, 0, kMaxRayDepth);
    if (axis.name == "light-count") parseInteger(what, v, 0, int(std::max<std::size_t>(lightCount, 0)));
    if (axis.name == "environment-rotation") parseNumber(what, v, Real(-360), Real(360));
    if (axis.name == "shininess" || axis.name == "crease-angle" || axis.name == "azimuth" || axis.name == "elevation" ||
        axis.name == "light-intensity")
      parseNumber(what, v, axis.name == "azimuth" || axis.name == "elevation" ? Real(-360) : Real(0), Real(1e6));
    if (axis.name == "zoom" || axis.name == "view-angle") parseNumber(what, v, Real(1e-3), Real(1e6));
    if (material || light) checkValue(axis, v, option);
  }
  return axis;
}

void applyToOptions(const SheetAxis& axis, const std::string& value, SceneOptions& o) {
  const std::string& a = axis.name;
  if (a == "model") o.model = value;
  else if (a == "shading") o.shading = value;
  else if (a == "convention") o.convention = value;
  else if (a == "renderer") o.renderer = value;
  else if (a == "samples") o.samples = std::stoi(value);
  else if (a == "max-depth") o.maxDepth = std::stoi(value);
  else if (a == "tone-map") o.toneMap = value;
  else if (a == "encoding") o.encoding = value;
  else if (a == "environment") o.environment = value;  // none, studio or a map file (read for each panel's scene)
  else if (a == "environment-rotation") o.environmentRotation = std::stod(value);
  else if (a == "normals") o.normals = value;
  else if (a == "crease-angle") o.creaseAngle = std::stod(value);
  else if (a == "azimuth") o.azimuth = std::stod(value);
  else if (a == "elevation") o.elevation = std::stod(value);
  else if (a == "zoom") o.zoom = std::stod(value);
  else if (a == "light-intensity") o.lightIntensity = std::stod(value);
  else if (a == "view-angle") o.viewAngle = std::stod(value);
}

void applyToScene(const SheetAxis& axis, const std::string& value, Scene& s) {
  const std::string& a = axis.name;
  if (a == "shininess") {
    const Real n = parseNumber("shininess", value, 0, Real(1e6));
    for (Object& o : s.objects) o.material.shininess = n;
  } else if (a == "light-count") {
    const int n = parseInteger("light-count", value, 0, int(s.lights.size()));
    s.lights.resize(std::size_t(n));
  } else if (a.rfind("material.", 0) == 0) {
    const std::string key = a.substr(9);
    const auto kind = materialKeys().find(key);
    if (kind == materialKeys().end()) throw InputError(a + ": expected material." + keyList(materialKeys()));
    for (Object& o : s.objects) {
      Material& m = o.material;
      if (kind->second == ValueKind::Colour) {
        const Vec3 c = threeNumbers(a, value, true);
        if (key == "ambient") m.ambient = Color4(c, m.ambient.a);
        if (key == "diffuse") m.diffuse = Color4(c, m.diffuse.a);
        if (key == "specular") m.specular = Color4(c, m.specular.a);
        if (key == "emission") m.emission = Color4(c, m.emission.a);
        if (key == "base_color") {
          PhysicalMaterial p = physicalOf(m);
          p.baseColor = c;
          glFromPhysical(m, p);
        }
      } else {
        const Real v = parseNumber(a, value, 0, kind->second == ValueKind::UnitNumber ? Real(1) : Real(1e6));
        if (key == "shininess") m.shininess = v;
        if (key == "metallic" || key == "roughness") {
          PhysicalMaterial p = physicalOf(m);
          (key == "metallic" ? p.metallic : p.roughness) = v;
          glFromPhysical(m, p);
        }
      }
    }
  } else if (a.rfind("light.", 0) == 0) {
    const auto dot = a.find('.', 6);
    const std::string key = dot == std::string::npos ? "" : a.substr(dot + 1);
    const auto kind = lightKeys().find(key);
    if (dot == std::string::npos || kind == lightKeys().end())
      throw InputError(a + ": expected light.N." + keyList(lightKeys()) + " (N counts from 0)");
    const int index = parseInteger(a, a.substr(6, dot - 6), 0, 1 << 20);
    if (std::size_t(index) >= s.lights.size())
      throw InputError(a + ": the scene has " + std::to_string(s.lights.size()) + " lights (light.0 .. light." +
                       std::to_string(int(s.lights.size()) - 1) + ")");
    Light& l = s.lights[std::size_t(index)];
    if (key == "position") {
      // x,y,z (a point) or x,y,z,w (w = 0: a direction), as the scene format's position.
      const std::size_t commas = std::size_t(std::count(value.begin(), value.end(), ','));
      if (commas == 3) {
        const auto last = value.rfind(',');
        l.position = Vec4(parseVec3(a, value.substr(0, last)), parseNumber(a, value.substr(last + 1), -1e6, 1e6));
      } else {
        l.position = Vec4(parseVec3(a, value), 1);
      }
    } else if (kind->second == ValueKind::Colour) {
      const bool colour = key == "ambient" || key == "diffuse" || key == "specular";
      const Vec3 v = threeNumbers(a, value, colour);
      if (key == "ambient") l.ambient = v;
      if (key == "diffuse") l.diffuse = v;
      if (key == "specular") l.specular = v;
      if (key == "spot_direction") l.spotDirection = v;
      if (key == "attenuation") {
        if (v.x < 0 || v.y < 0 || v.z < 0 || v == Vec3(0)) throw InputError(a + ": expected three numbers ≥ 0, not all 0");
        l.attenuation = v;
      }
    } else {
      const Real v = parseNumber(a, value, 0, key == "spot_cutoff" ? Real(180) : Real(128));
      if (key == "spot_cutoff") {
        if (v > 90 && v != 180) throw InputError(a + ": expected an angle in [0, 90] or 180");
        l.spotCutoff = v;
      } else {
        l.spotExponent = v;
      }
    }
  }
}

}  // namespace illum::cli
