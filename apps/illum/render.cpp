// `illum render [SCENE.json] [-o OUT.png]`: render a scene file, or the built-in scene, to PNG.
#include <illum/error.h>
#include <illum/image.h>
#include <illum/render.h>
#include <illum/scene.h>

#include "cli_values.h"
#include "commands.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

namespace illum::cli {
namespace {

struct RenderOptions {
  std::string scene;
  std::string output = "illum.png";
  std::optional<int> width, height;
  std::string model, shading, background;
  bool verbose = false;
};

int runRender(const RenderOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  Scene scene = o.scene.empty() ? defaultScene() : loadSceneFile(o.scene);
  if (o.width) scene.width = *o.width;
  if (o.height) scene.height = *o.height;
  if (!o.model.empty()) {
    const auto m = parseLightingModel(o.model);
    if (!m) throw InputError("--model: expected blinn-phong, phong or lambert, got \"" + o.model + "\"");
    scene.model = *m;
  }
  if (!o.shading.empty()) {
    const auto s = parseShading(o.shading);
    if (!s) throw InputError("--shading: expected flat, gouraud or phong, got \"" + o.shading + "\"");
    scene.shading = *s;
  }
  if (!o.background.empty()) scene.background = Color4(parseColor("--background", o.background, true), 1);

  RenderStats stats;
  const Image image = renderScene(scene, &stats);
  writePng(o.output, image);
  if (o.verbose) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "illum: %dx%d, %zu triangles in, %zu drawn, %zu fragments shaded, %.1f ms\n",
                 scene.width, scene.height, stats.trianglesIn, stats.trianglesDrawn, stats.fragmentsShaded, ms);
  }
  std::printf("%s\n", o.output.c_str());
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file (or, with none, the built-in scene) to PNG");
  cmd->add_option("scene", o->scene, "Scene file (JSON, docs/scene-format.md); none renders the built-in scene");
  cmd->add_option("-o,--output", o->output, "Output PNG, written atomically")->capture_default_str();
  cmd->add_option("--width", o->width, "Image width in pixels")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", o->height, "Image height in pixels")->check(CLI::Range(1, 16384));
  cmd->add_option("--model", o->model, "Lighting model: blinn-phong, phong or lambert");
  cmd->add_option("--shading", o->shading, "Shading frequency: flat, gouraud or phong");
  cmd->add_option("--background", o->background, "Background colour R,G,B in [0,1] (linear) or #rrggbb (sRGB)");
  cmd->add_flag("-v,--verbose", o->verbose, "Print triangle and fragment counts and the time taken");
  return [o] { return runRender(*o); };
}

}  // namespace illum::cli
