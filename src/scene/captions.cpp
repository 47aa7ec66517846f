#include <illum/captions.h>

#include <illum/error.h>
#include <illum/lighting.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace illum {
namespace {

std::string number(Real x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", double(x));
  return buf;
}

template <typename V>
std::string vector(const V& v, int n) {
  std::string text = "(";
  for (int i = 0; i < n; ++i) text += (i ? ", " : "") + number(v[i]);
  return text + ")";
}

std::vector<std::string> split(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) parts.push_back(key.substr(start, dot - start));
  parts.push_back(key.substr(start));
  return parts;
}

// The index N of "light.N..." or "object.N...", within `count`.
std::size_t index(const std::string& key, const std::string& text, std::size_t count, const char* what) {
  const bool digits = !text.empty() && text.size() < 6 && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits) throw InputError("{" + key + "}: expected " + what + ".N with N a number from 0");
  const std::size_t n = std::stoul(text);
  if (n >= count)
    throw InputError("{" + key + "}: the scene has " + std::to_string(count) + " " + what + (count == 1 ? "" : "s") +
                     (count ? " (" + std::string(what) + ".0 .. " + what + "." + std::to_string(count - 1) + ")" : ""));
  return n;
}

bool hasSpecularLobe(LightingModel model) {
  return model == LightingModel::Phong || model == LightingModel::BlinnPhong || model == LightingModel::CookTorrance;
}

std::string highlight(const Material& m, LightingModel model) {
  if (!hasSpecularLobe(model)) return "no specular";
  if (model == LightingModel::CookTorrance) return "roughness " + number(physicalOf(m).roughness);
  if (m.specular.r == 0 && m.specular.g == 0 && m.specular.b == 0) return "no specular";
  return "n = " + number(m.shininess);
}

std::string lightValue(const Light& l, const std::string& key, const std::string& whole) {
  if (key == "position") return vector(l.position, 4);
  if (key == "ambient") return vector(l.ambient, 3);
  if (key == "diffuse") return vector(l.diffuse, 3);
  if (key == "specular") return vector(l.specular, 3);
  if (key == "attenuation") return vector(l.attenuation, 3);
  if (key == "spot_direction") return vector(l.spotDirection, 3);
  if (key == "spot_cutoff") return number(l.spotCutoff);
  if (key == "spot_exponent") return number(l.spotExponent);
  throw InputError("{" + whole + "}: expected light.N.position, ambient, diffuse, specular, attenuation, spot_direction, "
                   "spot_cutoff or spot_exponent");
}

std::string materialValue(const Material& m, const std::string& key, const std::string& whole) {
  if (key == "ambient") return vector(m.ambient, 3);
  if (key == "diffuse") return vector(m.diffuse, 3);
  if (key == "specular") return vector(m.specular, 3);
  if (key == "emission") return vector(m.emission, 3);
  if (key == "shininess") return number(m.shininess);
  if (key == "base_color") return vector(physicalOf(m).baseColor, 3);
  if (key == "metallic") return number(physicalOf(m).metallic);
  if (key == "roughness") return number(physicalOf(m).roughness);
  throw InputError("{" + whole + "}: expected object.N.material.ambient, diffuse, specular, emission, shininess, "
                   "base_color, metallic or roughness");
}

std::string value(const std::string& key, const Scene& scene) {
  const std::vector<std::string> p = split(key);
  if (key == "model") return std::string(toString(scene.model));
  if (key == "model.description") return describeModel(scene.model, scene.lightModel.convention);
  if (key == "convention") return std::string(toString(scene.lightModel.convention));
  if (key == "convention.description") return describeConvention(scene.lightModel.convention);
  if (key == "shading") return std::string(toString(scene.shading));
  if (key == "shading.description") return describeShading(scene.shading, scene.renderer);
  if (key == "renderer") return std::string(toString(scene.renderer));
  if (p[0] == "light" && p.size() == 3) return lightValue(scene.lights[index(key, p[1], scene.lights.size(), "light")], p[2], key);
  if (p[0] == "object" && p.size() >= 3) {
    const Object& o = scene.objects[index(key, p[1], scene.objects.size(), "object")];
    const LightingModel model = modelOf(o.material, scene.model);
    if (p.size() == 3 && p[2] == "model") return std::string(toString(model));
    if (p.size() == 3 && p[2] == "highlight") return highlight(o.material, model);
    if (p.size() == 4 && p[2] == "material") return materialValue(o.material, p[3], key);
  }
  throw InputError("{" + key + "}: expected {model}, {model.description}, {convention}, {convention.description}, "
                   "{shading}, {shading.description}, {renderer}, "
                   "{light.N.KEY}, {object.N.material.KEY}, {object.N.model} or {object.N.highlight}");
}

}  // namespace

std::string expandCaption(const std::string& text, const Scene& scene) {
  std::string out;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t open = text.find('{', at);
    if (open == std::string::npos) {
      out += text.substr(at);
      break;
    }
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) throw InputError("\"" + text + "\": a { without its }");
    out += text.substr(at, open - at) + value(text.substr(open + 1, close - open - 1), scene);
    at = close + 1;
  }
  return out;
}

std::string describeModel(LightingModel model, Convention convention) {
  if (follows(model, convention) && convention == Convention::NoteShader) {
    switch (model) {
      case LightingModel::BlinnPhong: return "Blinn-Phong as seed 001's shader: ambient + (diffuse + specular (N·H)ⁿ)·(N·L)";
      case LightingModel::Phong: return "Phong as seed 001's shader: ambient + (diffuse + specular (R·V)ⁿ)·(N·L)";
      default: return "Lambert as seed 001's shader: the material's ambient + diffuse (N·L)";
    }
  }
  if (model == LightingModel::BlinnPhong && convention == Convention::NoteHalfSum)
    return "Blinn-Phong with seed 001's H = (L + V)/2: ambient + diffuse (N·L) + specular (N·H)ⁿ";
  switch (model) {
    case LightingModel::BlinnPhong: return "Blinn-Phong: ambient + diffuse (N·L) + specular (N·H)ⁿ";
    case LightingModel::Phong: return "Phong: ambient + diffuse (N·L) + specular (R·V)ⁿ";
    case LightingModel::Lambert: return "Lambert: ambient + diffuse (N·L), no specular";
    case LightingModel::CookTorrance: return "Cook-Torrance: diffuse + D·F·G / (4 (N·L)(N·V))";
    case LightingModel::Wylie: return "Wylie (1967): intensity ∝ 1/d, no angle";
    case LightingModel::Bouknight: return "Bouknight (1970): ambient + diffuse (N·L)";
  }
  return "";
}

std::string describeConvention(Convention convention) {
  switch (convention) {
    case Convention::GL: return "OpenGL's equation (2.1, §2.14.1)";
    case Convention::NoteShader: return "seed 001's shader: pixel = mat.ambient + (mat.diffuse + specular) × Ld·max(N·L, 0)";
    case Convention::NoteHalfSum: return "seed 001's H = (L + V) / 2, not normalised: (N·H)ⁿ with |H| ≤ 1";
    case Convention::NoteWorldSpace: return "seed 004's world space: V from each point to the camera (GL's local viewer)";
  }
  return "";
}

std::string describeShading(Shading shading, RendererKind renderer) {
  switch (renderer) {
    case RendererKind::Raster: break;
    case RendererKind::Whitted: return "Whitted ray tracing (1980): shadows, mirror and refracted rays";
    case RendererKind::Hall: return "Hall ray tracing (1983): Fresnel-weighted mirrors and glass, filtered light";
    case RendererKind::Path: return "path tracing (Kajiya 1986): the rendering equation, light bouncing everywhere";
  }
  switch (shading) {
    case Shading::Flat: return "flat shading: one colour per triangle, lit at its last vertex";
    case Shading::Gouraud: return "Gouraud shading: lit per vertex, colours interpolated";
    case Shading::Phong: return "Phong shading: normals interpolated, lit per pixel";
  }
  return "";
}

std::string whyUnlit(const Scene& scene) {
  if (scene.lights.empty()) return "no light";
  bool facing = false, inCone = false;
  for (const Object& o : scene.objects) {
    const Mat3 normalFromObject = glm::transpose(glm::inverse(Mat3(o.worldFromObject)));
    const Mesh& mesh = *o.mesh;
    for (std::size_t v = 0; v < mesh.positions.size() && v < mesh.normals.size(); ++v) {
      const Vec3 p = Vec3(o.worldFromObject * Vec4(mesh.positions[v], 1));
      const Vec3 n = glm::normalize(normalFromObject * mesh.normals[v]);
      for (const Light& l : scene.lights) {
        const Vec3 toLight = l.position.w != 0 ? Vec3(l.position) / l.position.w - p : Vec3(l.position);
        if (!(glm::length(toLight) > 0)) continue;
        const Vec3 L = glm::normalize(toLight);
        if (glm::dot(n, L) <= 0) continue;
        facing = true;
        const bool spot = l.spotCutoff != 180;
        if (!spot || glm::dot(-L, glm::normalize(l.spotDirection)) >= std::cos(glm::radians(l.spotCutoff))) inCone = true;
        if (inCone) return "";
      }
    }
  }
  if (!facing) return "every light is behind the surfaces";
  if (scene.renderer == RendererKind::Raster && scene.shading != Shading::Phong)
    return "no vertex lies inside a spot's cone (" + std::string(toString(scene.shading)) +
           " shading lights vertices only)";
  return "outside every spot's cone";
}

}  // namespace illum
