#include "pixel_report.h"

#include <illum/display.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace illum::cli {
namespace {

void row(std::FILE* out, const std::string& name, const Color3& c) {
  std::fprintf(out, "  %-22s %9.4f %9.4f %9.4f\n", name.c_str(), double(c.r), double(c.g), double(c.b));
}

std::string vec(const Vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4f, %.4f, %.4f)", double(v.x), double(v.y), double(v.z));
  return buf;
}

std::string rgba(const Color4& c) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.4f %.4f %.4f alpha %.4f", double(c.r), double(c.g), double(c.b), double(c.a));
  return buf;
}

int byte(Real c) { return int(std::lround(double(glm::clamp(c, Real(0), Real(1))) * 255)); }

std::string bytes(const std::array<std::uint8_t, 4>& b) {
  return std::to_string(b[0]) + " " + std::to_string(b[1]) + " " + std::to_string(b[2]) + " " + std::to_string(b[3]);
}

std::string displayName(const Display& d) {
  return "tone map " + std::string(toString(d.toneMap)) + ", encoding " + std::string(toString(d.encoding));
}

// The steps after the fragment: resolve, display, overlays, the file.
void printChain(std::FILE* out, const Scene& scene, const PixelChain& c, const std::uint8_t* file, bool traced) {
  if (!traced)
    std::fprintf(out, "  resolve: %s: bytes %s\n",
                 c.samples > 1 ? ("the mean of the pixel's " + std::to_string(c.samples) + " samples, blending included").c_str()
                               : "one sample per pixel, blending included",
                 bytes(c.resolved).c_str());
  // The rasterizer's lit colours took the tone map before they were quantised: its display step
  // is the encoding alone.
  const Display display = traced ? scene.display : encodingOnly(scene.display);
  std::fprintf(out, "  display (%s%s): bytes %s%s\n", displayName(display).c_str(),
               !traced && scene.display.toneMap != ToneMap::None ? "; the tone map was the fragment's" : "",
               bytes(c.displayed).c_str(), display.identity() ? " (unchanged: the equation's values are the bytes)" : "");
  for (const std::string& over : c.overlays) std::fprintf(out, "  drawn over it: %s\n", over.c_str());
  const std::array<std::uint8_t, 4> f{file[0], file[1], file[2], file[3]};
  if (c.overlays.empty() && f != c.displayed)
    std::fprintf(out, "  (the file's bytes differ from the display step's: an overlay this report does not name)\n");
}

// A multisampled pixel's samples, each as a pass at its position writes it.
void printSamples(std::FILE* out, const Scene& scene, const PixelProbe& p) {
  if (p.samples.empty()) return;
  std::fprintf(out, "  the pixel's %zu samples, each as a pass at its position draws it%s:\n", p.samples.size(),
               p.hit ? " (the fragment above is sample 0's)" : "");
  for (std::size_t i = 0; i < p.samples.size(); ++i) {
    const PixelProbe::Sample& s = p.samples[i];
    std::fprintf(out, "    sample %zu at (%+.3f, %+.3f): ", i, double(s.offset.x), double(s.offset.y));
    const Color4 c = s.hit ? s.written : scene.background;
    if (s.hit) std::fprintf(out, "object %zu, triangle %zu", s.object, s.triangle);
    else std::fprintf(out, "background");
    std::fprintf(out, ": bytes %d %d %d %d%s\n", byte(c.r), byte(c.g), byte(c.b), byte(c.a), s.blended ? " (blended)" : "");
  }
}

// The equation (OpenGL 2.1 §2.14.1) at one point, one light at a time, with each light's geometry;
// computed by the same accumulateLight the renderer uses. Returns the clamped colour.
// `toneMap`: the rasterizer's, applied to the sum before it is clamped (LightModel::toneMap); the
// ray tracers tone map the pixel's radiance instead.
Color4 printEquation(std::FILE* out, const Scene& scene, const Material& material, const Vec3& P, const Vec3& N,
                     ToneMap toneMap = ToneMap::None) {
  const LightingModel model = modelOf(material, scene.model);
  const Vec3 V = viewerDirection(P, scene.lightModel);
  std::fprintf(out, "  eye space: P = %s, N = %s, V = %s\n", vec(P).c_str(), vec(N).c_str(), vec(V).c_str());
  if (model == LightingModel::CookTorrance) {
    const PhysicalMaterial p = physicalOf(material);
    std::fprintf(out, "  cook-torrance (%s): base colour %s, metallic %.4f, roughness %.4f, f0 %s\n",
                p.distribution == Microfacet::GGX ? "GGX" : "Beckmann", vec(p.baseColor).c_str(), double(p.metallic),
                double(p.roughness), vec(p.f0).c_str());
  }
  if (follows(model, scene.lightModel.convention))
    std::fprintf(out, "  convention %s (light_model's convention: a lecture note's way, not GL's)\n",
                 std::string(toString(scene.lightModel.convention)).c_str());
  const SurfaceGeometry surface{P, N, V};
  const Mat4 view = scene.camera.viewFromWorld();
  std::fprintf(out, "  %-22s %9s %9s %9s\n", "", "R", "G", "B");
  const LightingTerms unlit = evaluateTerms({}, scene.lightModel, material, model, surface);
  row(out, "emission", unlit.emission);
  row(out, follows(model, scene.lightModel.convention) && scene.lightModel.convention == Convention::NoteShader
               ? "material ambient"
               : "global ambient",
      unlit.ambient);
  std::vector<EyeLight> lights;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const EyeLight& light = lights.emplace_back(toEyeSpace(scene.lights[i], view));
    LightingTerms share;
    LightDetail d;
    accumulateLight(share, light, material, model, surface, &d, scene.lightModel.convention);
    const std::string name = "light " + std::to_string(i);
    std::fprintf(out, "  %s: %s, L = %s", name.c_str(), d.positional ? "positional" : "directional", vec(d.L).c_str());
    if (d.positional) std::fprintf(out, ", distance %.4f", double(d.distance));
    std::fprintf(out, ", attenuation %.4f, spot factor %.4f%s; N·L = %.4f", double(d.attenuation), double(d.spot),
                light.isSpot() ? "" : " (no cone)", double(d.NoL));
    if (model == LightingModel::CookTorrance)
      std::fprintf(out, "; H = %s, N·H = %.4f, N·V = %.4f, V·H = %.4f; D = %.4f, V = G/(4 N·L N·V) = %.4f, F = %s",
                  vec(d.H).c_str(), double(d.NoH), double(d.NoV), double(d.VoH), double(d.D), double(d.visibility),
                  vec(d.F).c_str());
    else if (model == LightingModel::BlinnPhong)
      std::fprintf(out, "; H = %s, N·H = %.4f, (N·H)^%g = %.4f", vec(d.H).c_str(), double(d.NoH), double(material.shininess),
                  double(d.lobe));
    else if (model == LightingModel::Phong)
      std::fprintf(out, "; R = %s, R·V = %.4f, (R·V)^%g = %.4f", vec(d.R).c_str(), double(d.RoV), double(material.shininess),
                  double(d.lobe));
    std::fprintf(out, "\n");
    row(out, name + " ambient", d.terms.ambient);
    row(out, name + " diffuse", d.terms.diffuse);
    if (model == LightingModel::BlinnPhong || model == LightingModel::Phong || model == LightingModel::CookTorrance)
      row(out, name + " specular", d.terms.specular);
  }
  // The sum as the renderer forms it (the lights' shares above may differ from it in the last bit).
  const Color4 lit = clampedColor(evaluateTerms(lights, scene.lightModel, material, model, surface), material, toneMap);
  row(out, toneMap == ToneMap::None ? "total (clamped)" : "total (tone map " + std::string(toString(toneMap)) + ", clamped)",
      Color3(lit));
  return lit;
}

// A ray tracer's pixel: the primary ray's hit, the equation there without shadows, what each
// shadow ray found, and what the mirror, glass and see-through rays added.
void printTracedReport(std::FILE* out, const Scene& scene, const PixelProbe& p, const std::uint8_t* b, const PixelChain* chain) {
  std::fprintf(out, "pixel (%d, %d): object %zu, triangle %zu, %s face; %s; ray traced (%s): lit where the ray through the "
              "pixel's centre meets the surface, with the interpolated normal\n",
              p.x, p.y, p.object, p.triangle, p.frontFacing ? "front" : "back",
              std::string(toString(modelOf(p.material, scene.model))).c_str(), std::string(toString(scene.renderer)).c_str());
  std::fprintf(out, "  barycentric weights: %.4f %.4f %.4f\n", double(p.weights[0]), double(p.weights[1]),
              double(p.weights[2]));
  std::fprintf(out, " the local equation, every light seen:\n");
  printEquation(out, scene, p.material, p.eyePosition, p.eyeNormal);
  for (std::size_t i = 0; i < p.lightVisibility.size(); ++i) {
    const Color3& v = p.lightVisibility[i];
    const char* what = v == Color3(1) ? "seen" : v == Color3(0) ? "in shadow" : "seen through glass";
    std::fprintf(out, "  light %zu: %s (%.4f %.4f %.4f)%s\n", i, what, double(v.r), double(v.g), double(v.b),
                scene.rayTracing.shadows ? "" : ", shadows off");
  }
  std::fprintf(out, "  local colour with shadows%s: %s\n", scene.renderer == RendererKind::Hall ? " (Hall's terms)" : "",
              rgba(p.lit).c_str());
  if (p.textured)
    std::fprintf(out, p.texelIsBaseColor ? "  (the texel %s tinted the base colour before lighting)\n" : "  (× texel %s, GL_MODULATE)\n",
                rgba(p.texel).c_str());
  std::fprintf(out, "  with the reflected, refracted and see-through rays: %s = bytes %d %d %d %d\n", rgba(p.written).c_str(),
              byte(p.written.r), byte(p.written.g), byte(p.written.b), byte(p.written.a));
  if (chain) printChain(out, scene, *chain, b, true);
  std::fprintf(out, "  in the file: bytes %d %d %d %d%s\n", b[0], b[1], b[2], b[3],
              samplesPerPixel(scene) > 1 ? " (the mean of every sample of the pixel)" : "");
}

}  // namespace

PixelChain tracePixelChain(const Scene& scene, int x, int y) {
  PixelChain c;
  c.samples = scene.renderer == RendererKind::Raster ? scene.multisample : samplesPerPixel(scene);
  // The picture again without what is drawn after it (labels, the axes gizmo) and without the
  // display encoding: the framebuffer's bytes as resolved.
  Scene bare = scene;
  bare.labels.clear();
  bare.overlays.axes = false;
  bare.display = Display{};
  if (scene.renderer == RendererKind::Raster) bare.display.toneMap = scene.display.toneMap;  // the fragments'
  Renderer renderer;
  Image framebuffer;
  renderer.render(bare, framebuffer);
  const std::uint8_t* r = framebuffer.pixel(x, y);
  c.resolved = {r[0], r[1], r[2], r[3]};
  Image one(1, 1);
  std::copy(r, r + 4, one.rgba.begin());
  if (scene.renderer == RendererKind::Raster) {
    applyDisplay(one, encodingOnly(scene.display), &scene.background);
  } else {
    // The tracers encode each pixel's value, not its 8-bit byte: the picture drawn with the display.
    Scene displayed = bare;
    displayed.display = scene.display;
    renderer.render(displayed, framebuffer);
    std::copy(framebuffer.pixel(x, y), framebuffer.pixel(x, y) + 4, one.rgba.begin());
  }
  c.displayed = {one.rgba[0], one.rgba[1], one.rgba[2], one.rgba[3]};
  c.overlays = overlaysCovering(scene, x, y);
  return c;
}

void printPixelReport(const Scene& scene, const PixelProbe& p, const Image& image, std::FILE* out, const PixelChain* chain) {
  const std::uint8_t* b = image.pixel(p.x, p.y);
  if (!p.hit) {
    std::fprintf(out, "pixel (%d, %d): background, no surface drawn here%s\n", p.x, p.y,
                 p.samples.empty() ? "" : " (at sample 0)");
    if (scene.renderer == RendererKind::Raster) printSamples(out, scene, p);
    if (chain) printChain(out, scene, *chain, b, scene.renderer != RendererKind::Raster);
    std::fprintf(out, "  in the file: bytes %d %d %d %d\n", b[0], b[1], b[2], b[3]);
    return;
  }
  if (scene.renderer != RendererKind::Raster) {
    printTracedReport(out, scene, p, b, chain);
    return;
  }
  const char* shading = scene.shading == Shading::Flat      ? "flat shading: lit once, at the triangle's last vertex"
                        : scene.shading == Shading::Gouraud ? "Gouraud shading: lit at the vertices, colours interpolated"
                                                            : "Phong shading: lit here, with the interpolated normal";
  std::fprintf(out, "pixel (%d, %d): object %zu, triangle %zu, %s face; %s; %s\n", p.x, p.y, p.object, p.triangle,
              p.frontFacing ? "front" : "back", std::string(toString(modelOf(p.material, scene.model))).c_str(), shading);
  switch (scene.shading) {
    case Shading::Flat:
      std::fprintf(out, " the provoking vertex:\n");
      printEquation(out, scene, p.material, p.eyePosition, p.eyeNormal, scene.display.toneMap);
      std::fprintf(out, "  lit colour (the provoking vertex's, for the whole triangle): %s\n", rgba(p.lit).c_str());
      break;
    case Shading::Gouraud:
      for (std::size_t i = 0; i < 3; ++i) {
        std::fprintf(out, " vertex %zu of the drawn triangle:\n", i);
        printEquation(out, scene, p.vertexMaterials[i], p.vertexPositions[i], p.vertexNormals[i], scene.display.toneMap);
        std::fprintf(out, "  vertex colour used: %s\n", rgba(p.vertexColors[i]).c_str());
      }
      std::fprintf(out, "  perspective-correct weights: %.4f %.4f %.4f\n", double(p.weights[0]), double(p.weights[1]),
                  double(p.weights[2]));
      std::fprintf(out, "  lit colour (interpolated): %s\n", rgba(p.lit).c_str());
      break;
    case Shading::Phong:
      printEquation(out, scene, p.material, p.eyePosition, p.eyeNormal, scene.display.toneMap);
      std::fprintf(out, "  lit colour: %s\n", rgba(p.lit).c_str());
      break;
  }
  if (p.textured && p.texelIsBaseColor)
    std::fprintf(out, "  (the texel %s tinted the base colour before lighting)\n", rgba(p.texel).c_str());
  else if (p.textured)
    std::fprintf(out, "  × texel %s (GL_MODULATE)\n", rgba(p.texel).c_str());
  std::fprintf(out, "  fragment: %s = bytes %d %d %d %d%s\n", rgba(p.written).c_str(), byte(p.written.r), byte(p.written.g),
              byte(p.written.b), byte(p.written.a), p.blended ? ", blended over what was there (source over)" : "");
  printSamples(out, scene, p);
  if (chain) printChain(out, scene, *chain, b, false);
  std::fprintf(out, "  in the file: bytes %d %d %d %d\n", b[0], b[1], b[2], b[3]);
}

}  // namespace illum::cli
