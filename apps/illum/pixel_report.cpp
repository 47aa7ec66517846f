#include "pixel_report.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace illum::cli {
namespace {

void row(const std::string& name, const Color3& c) {
  std::printf("  %-22s %9.4f %9.4f %9.4f\n", name.c_str(), double(c.r), double(c.g), double(c.b));
}

int byte(Real c) { return int(std::lround(double(glm::clamp(c, Real(0), Real(1))) * 255)); }

}  // namespace

void printPixelReport(const Scene& scene, const PixelProbe& p) {
  if (!p.hit) {
    std::printf("pixel (%d, %d): background, no surface drawn here\n", p.x, p.y);
    return;
  }
  const char* shading = scene.shading == Shading::Flat      ? "flat shading: lit once, at the triangle's last vertex"
                        : scene.shading == Shading::Gouraud ? "Gouraud shading: lit at the vertices, colours interpolated"
                                                            : "Phong shading: lit here, with the interpolated normal";
  std::printf("pixel (%d, %d): object %zu, triangle %zu, %s face; %s; %s\n", p.x, p.y, p.object, p.triangle,
              p.frontFacing ? "front" : "back", std::string(toString(scene.model)).c_str(), shading);
  const Vec3 V = viewerDirection(p.eyePosition, scene.lightModel.localViewer);
  std::printf("  eye space: P = (%.4f, %.4f, %.4f), N = (%.4f, %.4f, %.4f), V = (%.4f, %.4f, %.4f)\n",
              double(p.eyePosition.x), double(p.eyePosition.y), double(p.eyePosition.z), double(p.eyeNormal.x),
              double(p.eyeNormal.y), double(p.eyeNormal.z), double(V.x), double(V.y), double(V.z));

  // The equation at that point, one light at a time (OpenGL 2.1 §2.14.1).
  const SurfaceGeometry surface{p.eyePosition, p.eyeNormal, V};
  const Mat4 view = scene.camera.viewFromWorld();
  std::printf("  %-22s %9s %9s %9s\n", "", "R", "G", "B");
  row("emission", Color3(p.material.emission));
  row("global ambient", scene.lightModel.ambient * Color3(p.material.ambient));
  LightingTerms total;
  total.emission = Color3(p.material.emission);
  total.ambient = scene.lightModel.ambient * Color3(p.material.ambient);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const EyeLight light = toEyeSpace(scene.lights[i], view);
    LightingTerms one;
    accumulateLight(one, light, p.material, scene.model, surface);
    const std::string name = "light " + std::to_string(i);
    row(name + " ambient", one.ambient);
    row(name + " diffuse", one.diffuse);
    if (scene.model != LightingModel::Lambert) row(name + " specular", one.specular);
    total.ambient += one.ambient;
    total.diffuse += one.diffuse;
    total.specular += one.specular;
  }
  const Color4 lit = clampedColor(total, p.material);
  row("total (clamped)", Color3(lit));
  std::printf("  written: %.4f %.4f %.4f alpha %.4f = bytes %d %d %d %d%s\n", double(p.written.r), double(p.written.g),
              double(p.written.b), double(p.written.a), byte(p.written.r), byte(p.written.g), byte(p.written.b),
              byte(p.written.a),
              scene.objects[p.object].diffuseTexture && !scene.objects[p.object].mesh->uvs.empty()
                  ? " (modulated by the texture)"
                  : "");
}

}  // namespace illum::cli
