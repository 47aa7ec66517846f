// A scene written back as a scene file (sceneJson): every key the reader takes, with the values
// the scene holds, so that reading it gives the same scene and `illum render` the same bytes.
#include <illum/error.h>
#include <illum/scene.h>

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <string>

namespace illum {
namespace {

using Json = nlohmann::ordered_json;  // keys in the order a person reads them

// The shortest decimal that reads back to the same Real (std::to_chars' guarantee), so that a
// written 0.8f is "0.8" and still exactly 0.8f when read.
Json number(Real x) {
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  const double value = std::stod(std::string(text, end));
  // Whole numbers as integers ("1", not "1.0"); −0 keeps its sign.
  if (value == std::trunc(value) && std::abs(value) < 1e15 && !(value == 0 && std::signbit(value)))
    return static_cast<long long>(value);
  return value;
}

Json numbers(std::initializer_list<Real> values) {
  Json a = Json::array();
  for (Real v : values) a.push_back(number(v));
  return a;
}
Json of(const Vec3& v) { return numbers({v.x, v.y, v.z}); }
Json of(const Vec4& v) { return numbers({v.x, v.y, v.z, v.w}); }

Json camera(const Camera& c) {
  Json j;
  j["eye"] = of(c.eye);
  j["center"] = of(c.center);
  j["up"] = of(c.up);
  j["fovy"] = number(c.fovy);
  j["near"] = number(c.near);
  j["far"] = number(c.far);
  j["projection"] = c.projection == Projection::Orthographic ? "orthographic" : "perspective";
  if (c.projection == Projection::Orthographic) j["view_height"] = number(c.viewHeight);
  return j;
}

Json light(const Light& l) {
  Json j;
  j["position"] = of(l.position);
  j["ambient"] = of(l.ambient);
  j["diffuse"] = of(l.diffuse);
  j["specular"] = of(l.specular);
  j["attenuation"] = of(l.attenuation);
  j["spot_direction"] = of(l.spotDirection);
  j["spot_exponent"] = number(l.spotExponent);
  j["spot_cutoff"] = number(l.spotCutoff);
  return j;
}

bool isDefault(const SurfaceOptics& o) {
  const SurfaceOptics d;
  return o.reflective == d.reflective && o.transmissive == d.transmissive && o.ior == d.ior &&
         !o.transmissionShininess && o.filter == d.filter;
}

Json material(const Material& m, const SurfaceOptics& o) {
  Json j;
  if (m.physicallyBased) {
    j["base_color"] = of(Color4(m.physical.baseColor, m.diffuse.a));
    j["metallic"] = number(m.physical.metallic);
    j["roughness"] = number(m.physical.roughness);
    j["f0"] = of(m.physical.f0);
    j["distribution"] = m.physical.distribution == Microfacet::Beckmann ? "beckmann" : "ggx";
  } else {
    j["ambient"] = of(m.ambient);
    j["diffuse"] = of(m.diffuse);
    j["specular"] = of(m.specular);
    j["shininess"] = number(m.shininess);
  }
  // Colours are at most 1: an emitter brighter than white keeps its colour and says how bright.
  const Real brightest = std::max({m.emission.r, m.emission.g, m.emission.b});
  if (brightest > 1) {
    j["emission"] = of(Color4(Color3(m.emission) / brightest, m.emission.a));
    j["emission_strength"] = number(brightest);
  } else {
    j["emission"] = of(m.emission);
  }
  if (m.model) j["model"] = std::string(toString(*m.model));
  if (!isDefault(o)) {
    j["reflective"] = of(o.reflective);
    j["transmissive"] = of(o.transmissive);
    j["ior"] = number(o.ior);
    if (o.transmissionShininess) j["transmission_shininess"] = number(*o.transmissionShininess);
    j["filter"] = of(o.filter);
  }
  return j;
}

// Row by row, as the reader takes it.
Json transform(const Mat4& m) {
  Json rows = Json::array();
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) rows.push_back(number(m[col][row]));
  return Json::array({Json{{"matrix", rows}}});
}

// A "mesh" value with its type first and the rest in alphabetical order, however it was given:
// a scene written, read and written again is the same text.
Json mesh(const std::string& text) {
  const nlohmann::json given = nlohmann::json::parse(text);
  Json j;
  if (given.contains("type")) j["type"] = given["type"];
  for (const auto& [key, value] : given.items())
    if (key != "type") j[key] = value;
  return j;
}

const ObjectSource& sourceOf(const Object& o, std::size_t index) {
  if (!o.source)
    throw Error("object " + std::to_string(index) + " was not made by a scene file, a model file or the built-in scene: it cannot be written as one");
  return *o.source;
}

// The scene's objects as the scene file's: a model file's instances together as the one object
// that brings them, the materials that differ from the file's given part by part.
Json objects(const std::vector<Object>& all) {
  Json out = Json::array();
  for (std::size_t i = 0; i < all.size();) {
    const ObjectSource& s = sourceOf(all[i], i);
    Json j;
    j["mesh"] = mesh(*s.mesh);
    if (s.transform != Mat4(1)) j["transform"] = transform(s.transform);
    if (!s.fileMaterial) {
      j["material"] = material(all[i].material, all[i].optics);
      out.push_back(std::move(j));
      ++i;
      continue;
    }
    if (s.part != 0 || i + std::size_t(s.parts) > all.size())
      throw Error("object " + std::to_string(i) + " is one mesh of a model file whose others are not in the scene: it cannot be written");
    Json materials = Json::array();
    bool changed = false;
    for (int p = 0; p < s.parts; ++p) {
      const Object& part = all[i + std::size_t(p)];
      const ObjectSource& ps = sourceOf(part, i + std::size_t(p));
      if (ps.mesh != s.mesh || ps.part != p)
        throw Error("object " + std::to_string(i + std::size_t(p)) + " is out of its model file's order: it cannot be written");
      const bool own = part.material == *ps.fileMaterial && isDefault(part.optics);
      materials.push_back(own ? Json() : material(part.material, part.optics));
      changed |= !own;
    }
    if (changed) j["materials"] = std::move(materials);
    out.push_back(std::move(j));
    i += std::size_t(s.parts);
  }
  return out;
}

Json label(const Label& l) {
  Json j;
  j["text"] = l.text;
  if (l.position) j["position"] = of(*l.position);
  if (l.pixel) j["pixel"] = numbers({l.pixel->x, l.pixel->y});
  j["color"] = of(l.color);
  j["size"] = number(l.size);
  return j;
}

// JSON as a person would lay it out: objects one key a line, arrays of numbers on one line.
void write(const Json& j, std::string& out, int depth) {
  const std::string pad(std::size_t(2 * (depth + 1)), ' '), close(std::size_t(2 * depth), ' ');
  const auto flat = [](const Json& a) {
    for (const Json& v : a)
      if (v.is_structured()) return false;
    return true;
  };
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      out += first ? "" : ",\n";
      out += pad + Json(key).dump() + ": ";
      write(value, out, depth + 1);
      first = false;
    }
    out += "\n" + close + "}";
  } else if (j.is_array() && !j.empty() && !flat(j)) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += i ? ",\n" + pad : pad;
      write(j[i], out, depth + 1);
    }
    out += "\n" + close + "]";
  } else if (j.is_array()) {
    out += "[";
    for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
    out += "]";
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string sceneJson(const Scene& s) {
  Json j;
  j["version"] = 1;
  j["width"] = s.width;
  j["height"] = s.height;
  j["background"] = of(s.background);
  j["renderer"] = std::string(toString(s.renderer));
  j["model"] = std::string(toString(s.model));
  j["shading"] = std::string(toString(s.shading));
  j["multisample"] = s.multisample;
  j["max_depth"] = s.rayTracing.maxDepth;
  j["shadows"] = s.rayTracing.shadows;
  j["denoise"] = s.rayTracing.denoise;
  if (s.rayTracing.samples) j["samples"] = *s.rayTracing.samples;
  if (s.rayTracing.seed != 0) j["seed"] = s.rayTracing.seed;
  if (s.environment.studio)
    j["studio_environment"] = true;
  else if (s.rayTracing.environmentMap)
    j["environment_map"] = std::filesystem::absolute(s.rayTracing.environmentMap->path()).lexically_normal().string();
  j["environment_lighting"] = std::string(toString(s.environment.lighting));
  j["environment_rotation"] = number(s.environment.rotation);
  j["environment_background"] = std::string(toString(s.environment.background));
  j["environment"] = of(s.rayTracing.environment);
  j["tone_map"] = std::string(toString(s.display.toneMap));
  j["encoding"] = std::string(toString(s.display.encoding));
  j["blend"] = s.blend;
  j["point_size"] = number(s.pointSize);
  j["line_width"] = number(s.lineWidth);
  j["overlays"] = Json{{"edges", s.overlays.edges}, {"grid", s.overlays.grid}, {"axes", s.overlays.axes}};
  if (s.ambientOcclusion.enabled) {
    Json ao;
    ao["rays"] = s.ambientOcclusion.rays;
    if (s.ambientOcclusion.distance) ao["distance"] = number(*s.ambientOcclusion.distance);
    j["ambient_occlusion"] = std::move(ao);
  } else {
    j["ambient_occlusion"] = false;
  }
  j["camera"] = camera(s.camera);
  j["light_model"] = Json{{"ambient", of(s.lightModel.ambient)},
                          {"local_viewer", s.lightModel.localViewer},
                          {"two_sided", s.lightModel.twoSided}};
  if (s.lightModel.convention != Convention::GL)
    j["light_model"]["convention"] = std::string(toString(s.lightModel.convention));
  j["lights"] = Json::array();
  for (const Light& l : s.lights) j["lights"].push_back(light(l));
  j["objects"] = objects(s.objects);
  if (!s.labels.empty()) {
    j["labels"] = Json::array();
    for (const Label& l : s.labels) j["labels"].push_back(label(l));
  }
  std::string out;
  write(j, out, 0);
  return out + "\n";
}

}  // namespace illum
