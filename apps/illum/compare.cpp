// `illum compare [SCENE.json | MODEL] --rows AXIS --cols AXIS [--diff A,B] -o sheet.png`: one
// picture of a scene under every combination of two settings, labelled; by default lighting
// models against shading frequencies. With --diff, a panel per row (or column) shows where two of
// the settings differ, with the figures.
#include <illum/error.h>
#include <illum/image.h>
#include <illum/output_file.h>
#include <illum/render.h>
#include <illum/sheet.h>

#include "commands.h"
#include "compare.h"
#include "scene_options.h"
#include "sheet_axes.h"
#include "sheet_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace illum::cli {
namespace {

std::string figures(const DifferencePanel& d) {
  char text[96];
  if (std::isinf(d.psnr)) std::snprintf(text, sizeof text, "identical");
  else std::snprintf(text, sizeof text, "max %d/255 · PSNR %.1f dB", d.maxError, d.psnr);
  return text;
}

}  // namespace

Sheet compareSheet(const CompareOptions& o, ModelCache* models) {
  const ThreadLimit limit(o.scene);
  ModelCache own;
  ModelCache& cache = models ? *models : own;
  SceneOptions base = o.scene;
  const Scene first = prepareScene(base, nullptr, &cache);
  defaultPanelSize(base, first);
  const SheetAxis rows = parseSheetAxis("--rows", o.rows, first.lights.size());
  const SheetAxis cols = parseSheetAxis("--cols", o.cols, first.lights.size());
  if (rows.name == cols.name) throw InputError("--rows and --cols: expected two different axes, got " + rows.name + " twice");
  if (rows.values.size() * cols.values.size() > 64)
    throw InputError("--rows and --cols: at most 64 panels, got " + std::to_string(rows.values.size()) + " × " +
                     std::to_string(cols.values.size()));

  // --diff A,B: two values of one axis, compared in a panel per row (or column).
  std::optional<std::pair<std::size_t, std::size_t>> diffCols, diffRows;
  if (!o.diff.empty()) {
    const auto comma = o.diff.find(',');
    const std::string a = o.diff.substr(0, comma), b = comma == std::string::npos ? "" : o.diff.substr(comma + 1);
    const auto find = [](const SheetAxis& axis, const std::string& v) {
      return std::size_t(std::find(axis.values.begin(), axis.values.end(), v) - axis.values.begin());
    };
    if (find(cols, a) < cols.values.size() && find(cols, b) < cols.values.size() && a != b)
      diffCols = {find(cols, a), find(cols, b)};
    else if (find(rows, a) < rows.values.size() && find(rows, b) < rows.values.size() && a != b)
      diffRows = {find(rows, a), find(rows, b)};
    else
      throw InputError("--diff: expected two different values of the rows' or the columns' axis, A,B, got \"" + o.diff + "\"");
  }

  checkSheetPixels((rows.values.size() + (diffRows ? 1 : 0)) * (cols.values.size() + (diffCols ? 1 : 0)), base, first);

  Sheet sheet;
  // One display for every panel, unless the display is what the sheet compares.
  const bool oneDisplay = rows.name != "tone-map" && rows.name != "encoding" && cols.name != "tone-map" && cols.name != "encoding";
  sheet.title = inputName(o.scene) + " · rows: " + rows.name + " · columns: " + cols.name;
  if (oneDisplay) sheet.subtitle = displayCaption(first.display);
  sheet.corner = rows.name + " \\ " + cols.name;
  sheet.rowLabels = rows.values;
  sheet.columnLabels = cols.values;
  Renderer renderer;
  std::vector<std::vector<Image>> images(rows.values.size());
  std::vector<std::vector<std::string>> captions(rows.values.size());  // why a black panel is black
  for (std::size_t r = 0; r < rows.values.size(); ++r)
    for (std::size_t c = 0; c < cols.values.size(); ++c) {
      SceneOptions cell = base;
      applyToOptions(rows, rows.values[r], cell);
      applyToOptions(cols, cols.values[c], cell);
      cell.verbose = false;
      Scene scene = prepareScene(cell, nullptr, &cache);
      applyToScene(rows, rows.values[r], scene);
      applyToScene(cols, cols.values[c], scene);
      if (oneDisplay) scene.display = first.display;
      Image image;
      renderer.render(scene, image);
      captions[r].push_back(unlitPanelCaption(image, scene));
      images[r].push_back(std::move(image));
    }
  // The difference panels first, then every picture moved (not copied) into the sheet.
  std::vector<SheetPanel> rowDiffs, colDiffs;
  if (diffCols)
    for (std::size_t r = 0; r < rows.values.size(); ++r) {
      DifferencePanel d = differencePanel(images[r][diffCols->first], images[r][diffCols->second]);
      colDiffs.push_back({std::move(d.image), figures(d)});
    }
  if (diffRows)
    for (std::size_t c = 0; c < cols.values.size(); ++c) {
      DifferencePanel d = differencePanel(images[diffRows->first][c], images[diffRows->second][c]);
      rowDiffs.push_back({std::move(d.image), figures(d)});
    }
  for (std::size_t r = 0; r < rows.values.size(); ++r) {
    sheet.panels.emplace_back();
    for (std::size_t c = 0; c < cols.values.size(); ++c) sheet.panels.back().push_back({std::move(images[r][c]), captions[r][c]});
    if (diffCols) sheet.panels.back().push_back(std::move(colDiffs[r]));
  }
  if (diffCols) sheet.columnLabels.push_back(cols.values[diffCols->first] + " vs " + cols.values[diffCols->second]);
  if (diffRows) {
    sheet.panels.push_back(std::move(rowDiffs));
    sheet.rowLabels.push_back(rows.values[diffRows->first] + " vs " + rows.values[diffRows->second]);
  }

  return sheet;
}

namespace {

int runCompare(const CompareOptions& o) {
  checkSheetOutput(o.out);
  const Sheet sheet = compareSheet(o);
  writeSheet(sheet, o.out, o.scene.verbose,
             [&](std::size_t r, std::size_t c) { return sheet.rowLabels[r] + " / " + sheet.columnLabels[c]; });
  return 0;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Render a scene under two axes of settings into one labelled sheet");
  addCompareOptions(*cmd, *o);
  addSheetOutputOptions(*cmd, o->out);
  return [o] { return runCompare(*o); };
}

void addCompareOptions(CLI::App& command, CompareOptions& options) {
  CLI::App* cmd = &command;
  CompareOptions* o = &options;
  cmd->footer(
      "An axis is NAME or NAME=v1,v2,... (';' between values that hold commas):\n"
      "  model, shading, renderer, samples, max-depth, tone-map, encoding, normals, crease-angle,\n"
      "  azimuth, elevation, zoom, light-intensity, view-angle (as render's options),\n"
      "  shininess, light-count, material.KEY, light.N.KEY (as the scene file's keys).\n"
      "Example: illum compare --rows model=phong,blinn-phong --cols shininess=1,8,32,128 -o s.png");
  addSceneOptions(*cmd, o->scene);
  cmd->add_option("--rows", o->rows, "The axis down the sheet")->capture_default_str();
  cmd->add_option("--cols", o->cols, "The axis across the sheet")->capture_default_str();
  cmd->add_option("--diff", o->diff, "A,B: add panels showing where values A and B of one axis differ (max, PSNR)");
}

}  // namespace illum::cli
