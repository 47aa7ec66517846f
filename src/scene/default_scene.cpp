// The built-in scene: GLUT's five solids in five classic materials under three coloured lights,
// a positional key light with distance attenuation, a directional fill and a spot from behind.
#include <illum/captions.h>
#include <illum/scene.h>

#include "scene/mesh_json.h"

#include <glm/gtc/matrix_transform.hpp>

#include <memory>
#include <string>

namespace illum {
namespace {

Material material(Color3 ambient, Color3 diffuse, Color3 specular, Real shininess) {
  Material m;
  m.ambient = Color4(ambient, 1);
  m.diffuse = Color4(diffuse, 1);
  m.specular = Color4(specular, 1);
  m.shininess = shininess;
  return m;
}

// An object whose mesh is a scene file's "mesh" value: the scene can be written out as a file.
Object object(const std::string& mesh, Mat4 worldFromObject, Material m) {
  Object o;
  o.mesh = std::make_shared<const Mesh>(meshFromJson(mesh));
  o.worldFromObject = worldFromObject;
  o.material = m;
  auto source = std::make_shared<ObjectSource>();
  source->mesh = std::make_shared<const std::string>(mesh);
  source->transform = worldFromObject;
  o.source = std::move(source);
  return o;
}

}  // namespace

Scene defaultScene(LightingModel model, Shading shading, RendererKind renderer) {
  Scene s;
  s.model = model;
  s.shading = shading;
  s.renderer = renderer;
  s.width = 960;
  s.height = 540;
  s.background = {0.06, 0.07, 0.1, 1};
  s.camera.eye = {0, 2.2, 8.5};
  s.camera.center = {0, 0.1, 0};
  s.camera.fovy = 40;
  s.lightModel.ambient = {0.15, 0.15, 0.17};
  // What the ambient term stands for, to the path tracer: light arriving from everywhere.
  s.rayTracing.environment = s.lightModel.ambient;

  Light key;  // warm positional key light, upper left front, gently attenuated
  key.position = {-4, 5, 6, 1};
  key.diffuse = {1.0, 0.93, 0.8};
  key.specular = {1, 1, 1};
  key.attenuation = {0.7, 0.04, 0.008};
  Light fill;  // cool directional fill from the right
  fill.position = {1, 0.3, 0.4, 0};
  fill.diffuse = {0.2, 0.3, 0.5};
  fill.specular = {0.3, 0.4, 0.6};
  Light rim;  // magenta spot from behind and above, aimed at the middle of the row
  rim.position = {0, 6, -5, 1};
  rim.spotDirection = {0, -6, 5};
  rim.spotCutoff = 35;
  rim.spotExponent = 8;
  rim.diffuse = {0.6, 0.25, 0.5};
  rim.specular = {0.8, 0.4, 0.7};
  s.lights = {key, fill, rim};

  const auto at = [](Real x, Real y, Real z) { return glm::translate(Mat4(1), Vec3(x, y, z)); };
  const auto upright = [](Mat4 m) { return glm::rotate(m, glm::radians(Real(-90)), Vec3(1, 0, 0)); };
  // Red plastic sphere: white Blinn-Phong highlight on a saturated diffuse colour.
  s.objects.push_back(object(R"({"type": "sphere", "radius": 0.8, "slices": 48, "stacks": 32})", at(-3.4f, 0.8f, 0),
                             material({0.25, 0.03, 0.03}, {0.8, 0.1, 0.1}, {0.9, 0.9, 0.9}, 60)));
  // Polished gold torus: coloured specular, like a metal.
  s.objects.push_back(object(R"({"type": "torus", "inner_radius": 0.22, "outer_radius": 0.62, "sides": 32, "rings": 64})",
                             glm::rotate(at(-1.6f, 0.85f, 0), glm::radians(Real(-60)), Vec3(1, 0, 0)),
                             material({0.25, 0.2, 0.07}, {0.75, 0.6, 0.23}, {0.63, 0.56, 0.37}, 51)));
  // For the ray tracers: the metal mirrors its surroundings (a metal's high reflectance as a high
  // index: Fresnel gives 0.67 at normal incidence for n = 10).
  s.objects.back().optics.reflective = {0.6, 0.5, 0.3};
  s.objects.back().optics.ior = 10;
  // Porcelain teapot in the middle.
  s.objects.push_back(object(R"({"type": "teapot", "size": 0.9})", at(0.3f, 0.7f, 0.3f),
                             material({0.1, 0.14, 0.2}, {0.45, 0.6, 0.85}, {0.8, 0.8, 0.8}, 90)));
  // Matte green cone: Lambert only, no specular colour.
  s.objects.push_back(object(R"({"type": "cone", "base": 0.7, "height": 1.7, "slices": 40, "stacks": 10})", upright(at(2.2f, 0, 0)),
                             material({0.05, 0.2, 0.05}, {0.2, 0.65, 0.25}, {0, 0, 0}, 0)));
  // Violet cube with a broad, dull highlight.
  s.objects.push_back(object(R"({"type": "cube", "size": 1.1})",
                             glm::rotate(at(3.7f, 0.55f, -0.3f), glm::radians(Real(35)), Vec3(0, 1, 0)),
                             material({0.12, 0.06, 0.18}, {0.5, 0.3, 0.7}, {0.4, 0.4, 0.4}, 8)));
  // A floor makes the light's distance falloff and the spot visible.
  s.objects.push_back(object(R"({"type": "triangles", "positions": [-8, 0, -6, 8, 0, -6, 8, 0, 6, -8, 0, 6],
                                 "normals": [0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0], "indices": [0, 3, 2, 0, 2, 1]})",
                             Mat4(1),
                             material({0.12, 0.12, 0.13}, {0.42, 0.42, 0.45}, {0.25, 0.25, 0.25}, 30)));
  s.objects.back().optics.reflective = Color3(0.3f);  // a polished floor, for the ray tracers

  // Say what the picture shows.
  const auto caption = [&](Real x, const char* text) {
    Label l;
    l.text = text;
    l.position = Vec3(x, 0, 1.0f);
    l.size = 15;
    l.color = {0.92, 0.92, 0.92};
    s.labels.push_back(l);
  };
  // Templates (captions.h): each names the highlight as the model drawing it sees it.
  caption(-3.4f, "plastic, {object.0.highlight}");
  caption(-1.55f, "gold, {object.1.highlight}");
  caption(0.3f, "porcelain, {object.2.highlight}");
  caption(2.2f, "matte, {object.3.highlight}");
  caption(3.7f, "dull, {object.4.highlight}");
  const auto title = [&](Real y, const std::string& text, Real size) {
    Label l;
    l.text = text;
    l.pixel = Vec2(Real(s.width) / 2, y);
    l.size = size;
    s.labels.push_back(l);
  };
  title(30, "{model.description}", 20);
  title(54, "{shading.description}", 16);
  title(Real(s.height) - 14,
        "lights: warm key, positional with 1/(a + bd + cd²) · cool fill, directional · magenta spot from behind", 14);
  return s;
}

}  // namespace illum
