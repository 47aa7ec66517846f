// The names of the models and shading frequencies, and lights into eye space. The equation itself
// is in gl_lighting-inl.h (its one-point entry points in shade_points.cpp).
#include <illum/lighting.h>

#include <cmath>

namespace illum {

std::string_view toString(LightingModel model) {
  switch (model) {
    case LightingModel::BlinnPhong: return "blinn-phong";
    case LightingModel::Phong: return "phong";
    case LightingModel::Lambert: return "lambert";
    case LightingModel::CookTorrance: return "cook-torrance";
    case LightingModel::Wylie: return "wylie";
    case LightingModel::Bouknight: return "bouknight";
  }
  return "?";
}

namespace {

// "a, b or c" of every name in `all`, in double quotes with `quoted`.
template <class E, std::size_t N>
std::string namesOf(const E (&all)[N], bool quoted) {
  std::string list;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) list += i + 1 == N ? " or " : ", ";
    const std::string name(toString(all[i]));
    list += quoted ? "\"" + name + "\"" : name;
  }
  return list;
}

}  // namespace

std::string lightingModelNames(bool quoted) { return namesOf(kLightingModels, quoted); }

std::string_view toString(Shading shading) {
  switch (shading) {
    case Shading::Flat: return "flat";
    case Shading::Gouraud: return "gouraud";
    case Shading::Phong: return "phong";
  }
  return "?";
}

std::optional<LightingModel> parseLightingModel(std::string_view name) {
  for (LightingModel m : kLightingModels)
    if (name == toString(m)) return m;
  return std::nullopt;
}

std::optional<Shading> parseShading(std::string_view name) {
  if (name == "flat") return Shading::Flat;
  if (name == "gouraud") return Shading::Gouraud;
  if (name == "phong") return Shading::Phong;
  return std::nullopt;
}

std::string_view toString(Convention convention) {
  switch (convention) {
    case Convention::GL: return "gl";
    case Convention::NoteShader: return "note-shader";
    case Convention::NoteHalfSum: return "note-half-sum";
    case Convention::NoteWorldSpace: return "note-world-space";
  }
  return "?";
}

std::optional<Convention> parseConvention(std::string_view name) {
  for (Convention c : kConventions)
    if (name == toString(c)) return c;
  return std::nullopt;
}

std::string conventionNames(bool quoted) { return namesOf(kConventions, quoted); }

EyeLight toEyeSpace(const Light& light, const Mat4& viewFromWorld) {
  EyeLight eye;
  // glLightfv(GL_POSITION) transforms the position by GL_MODELVIEW.
  eye.position = viewFromWorld * light.position;
  // GL_SPOT_DIRECTION is transformed by the upper-left 3×3 of GL_MODELVIEW (§2.14.1).
  Vec3 s = Mat3(viewFromWorld) * light.spotDirection;
  Real len = glm::length(s);
  eye.spotDirection = len > 0 ? s / len : Vec3(0, 0, -1);
  eye.ambient = light.ambient;
  eye.diffuse = light.diffuse;
  eye.specular = light.specular;
  eye.attenuation = light.attenuation;
  eye.spotExponent = light.spotExponent;
  eye.spotCutoff = light.spotCutoff;
  eye.spotCosCutoff = light.spotCutoff == 180 ? Real(-2)
                                              : std::cos(glm::radians(light.spotCutoff));
  return eye;
}

}  // namespace illum
