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

std::string lightingModelNames(bool quoted) {
  std::string list;
  const std::size_t n = std::size(kLightingModels);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) list += i + 1 == n ? " or " : ", ";
    const std::string name(toString(kLightingModels[i]));
    list += quoted ? "\"" + name + "\"" : name;
  }
  return list;
}

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
