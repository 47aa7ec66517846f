// `illum history [SCENE.json | MODEL] -o history.png`: the seeds' history of lighting in one
// picture: the same scene as each model from Wylie (1967) to Kajiya (1986) drew it, in order, each
// panel captioned with its year, its authors and its formula.
#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>
#include <illum/render.h>
#include <illum/sheet.h>

#include "commands.h"
#include "history.h"
#include "scene_options.h"
#include "sheet_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace illum::cli {
namespace {

// One step of the history: who, when, what, and how illum draws it.
struct Step {
  const char* year;
  const char* authors;
  const char* formula;
  const char* model;
  const char* shading;
  const char* renderer;
};

constexpr Step kSteps[] = {
    {"1967", "Wylie, Romney, Evans, Erdahl", "I ∝ 1/d from a light at the eye", "wylie", "phong", "raster"},
    {"1970", "Bouknight", "I = Ia ka + Il kd cos θ, per polygon", "bouknight", "flat", "raster"},
    {"1971", "Gouraud", "intensities interpolated from the vertices", "lambert", "gouraud", "raster"},
    {"1975", "Phong", "+ ks (R·V)ⁿ, normals interpolated", "phong", "phong", "raster"},
    {"1977", "Blinn", "+ ks (N·H)ⁿ, H = (L+V)/|L+V|", "blinn-phong", "phong", "raster"},
    {"1980", "Whitted", "I = local + kr R + kt T, ray traced", "blinn-phong", "phong", "whitted"},
    {"1982", "Cook, Torrance", "D·F·G / (4 (N·L)(N·V))", "cook-torrance", "phong", "raster"},
    {"1983", "Hall, Greenberg", "kr F and kt (1−F): Fresnel-weighted, filtered", "blinn-phong", "phong", "hall"},
    {"1986", "Kajiya", "L = Lₑ + ∫ f Lᵢ cos θ dω, path traced", "cook-torrance", "phong", "path"},
};
constexpr int kColumns = 3;

// Wylie et al. lit their half-tone pictures from the observer: one light at the eye, as bright as
// the distance to what is looked at, so that the middle of the picture has its full colour.
void lightFromTheEye(Scene& scene) {
  Light light;
  light.position = Vec4(scene.camera.eye, 1);
  light.diffuse = Color3(glm::length(scene.camera.center - scene.camera.eye));
  light.specular = Color3(0);
  scene.lights = {light};
}

}  // namespace

Sheet historySheet(const SceneOptions& o, ModelCache* models) {
  const ThreadLimit limit(o);
  if (!o.model.empty() || !o.shading.empty() || !o.renderer.empty())
    throw InputError("--model, --shading and --renderer: the history sets them panel by panel; use `illum render` for one");
  ModelCache own;
  ModelCache& cache = models ? *models : own;
  SceneOptions base = o;
  const Scene first = prepareScene(base, nullptr, &cache);
  defaultPanelSize(base, first);
  checkSheetPixels(std::size(kSteps), base, first);
  Sheet sheet;
  sheet.title = "Lighting from Wylie (1967) to Kajiya (1986): " + inputName(o);
  sheet.subtitle = displayCaption(first.display);
  Renderer renderer;
  int index = 0;
  for (const Step& step : kSteps) {
    SceneOptions cell = base;
    cell.model = step.model;
    cell.shading = step.shading;
    cell.renderer = step.renderer;
    cell.verbose = false;
    Scene scene = prepareScene(cell, nullptr, &cache);
    if (std::string(step.model) == "wylie") lightFromTheEye(scene);
    scene.display = first.display;  // the Kajiya panel's radiance through the sheet's one transform
    Image image;
    renderer.render(scene, image);
    if (index % kColumns == 0) sheet.panels.emplace_back();
    const std::string unlit = unlitPanelCaption(image, scene);
    sheet.panels.back().push_back(
        {std::move(image), std::string(step.year) + " · " + step.authors + "\n" + step.formula + (unlit.empty() ? "" : "\n" + unlit)});
    ++index;
  }
  return sheet;
}

namespace {

struct HistoryOptions {
  SceneOptions scene;
  SheetOutput out{"history.png", false, false, std::nullopt};
};

int runHistory(const HistoryOptions& o) {
  checkSheetOutput(o.out);
  const Sheet sheet = historySheet(o.scene);
  writeSheet(sheet, o.out, o.scene.verbose, [](std::size_t r, std::size_t c) {
    const Step& step = kSteps[r * kColumns + c];
    return std::string(step.year) + " / " + step.model + " " + step.shading + " " + step.renderer;
  });
  return 0;
}

}  // namespace

Command addHistoryCommand(CLI::App& app) {
  auto o = std::make_shared<HistoryOptions>();
  CLI::App* cmd = app.add_subcommand("history", "Render a scene by every model from Wylie (1967) to Kajiya (1986) on one sheet");
  cmd->footer(
      "Panels, in order: wylie (1967), bouknight (1970, flat), Gouraud (1971, lambert), Phong (1975),\n"
      "Blinn (1977), Whitted (1980), Cook-Torrance (1982), Hall (1983), Kajiya's path tracing (1986).");
  addSceneOptions(*cmd, o->scene);
  addSheetOutputOptions(*cmd, o->out);
  return [o] { return runHistory(*o); };
}

}  // namespace illum::cli
