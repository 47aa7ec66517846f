// `illum thumbnail INPUT OUTPUT SIZE`: a file manager's thumbnail, as the freedesktop thumbnailer
// specification calls it (`illum thumbnail %i %o %s` in illum.thumbnailer): the model framed and
// lit as `illum render` previews it, SIZE pixels on its longest side, on a transparent background,
// in the file's up axis, quietly, within a budget of time and memory that fits a file manager.
#include <illum/error.h>
#include <illum/limits.h>

#include "cli_values.h"
#include "commands.h"
#include "render_options.h"
#include "scene_options.h"

#include <memory>
#include <string>

namespace illum::cli {
namespace {

// What a file manager can wait for and spare, per file, unless the options say otherwise.
constexpr double kThumbnailSeconds = 5;
constexpr std::uint64_t kThumbnailMiB = 1024;
constexpr std::uint64_t kThumbnailTriangles = 5'000'000;

struct ThumbnailOptions {
  RenderOptions render;
  int size = 256;
};

int runThumbnail(ThumbnailOptions o) {
  RenderOptions& r = o.render;
  r.inputs = {r.scene.input};
  r.scene.input.clear();
  if (r.output.empty()) throw InputError("thumbnail: expected INPUT OUTPUT SIZE (illum thumbnail %i %o %s)");
  r.scene.resolution = std::to_string(o.size) + "," + std::to_string(o.size);
  r.scene.noBackground = true;
  r.scene.denseMeshesPerVertex = true;
  r.scene.studioForPhysicallyBased = false;  // the studio's light: 4.5 ms more of a 49 ms engine thumbnail
  r.quiet = true;
  if (r.scene.limits.maxSeconds == 0) r.scene.limits.maxSeconds = kThumbnailSeconds;
  if (r.scene.limits.maxMemoryMiB == 0) r.scene.limits.maxMemoryMiB = kThumbnailMiB;
  if (r.scene.limits.maxTriangles == Limits{}.maxTriangles) r.scene.limits.maxTriangles = kThumbnailTriangles;
  return runRender(r);
}

}  // namespace

Command addThumbnailCommand(CLI::App& app) {
  auto o = std::make_shared<ThumbnailOptions>();
  CLI::App* cmd = app.add_subcommand(
      "thumbnail", "A file manager's thumbnail of a model or scene file: illum thumbnail INPUT OUTPUT SIZE (%i %o %s)");
  cmd->footer(
      "The model as `illum render` previews it, SIZE pixels square, transparent around it, quiet (lit per vertex when it\n"
      "has more triangles than the thumbnail has pixels, unless --shading says otherwise); its import limited\n"
      "to 5 s, 1 GiB and 5 million triangles unless --max-time, --max-memory or --max-triangles say otherwise.\n"
      "OUTPUT's extension says its format (.png unless told). Installed as illum.thumbnailer (docs/cli.md).");
  addSceneOptions(*cmd, o->render.scene, nullptr);
  cmd->get_option("input")->required();
  cmd->add_option("output", o->render.output, "The thumbnail (PNG, or as its extension says)")->required();
  cmd->add_option("size", o->size, "Pixels on the thumbnail's longest side")->required()->check(wholeRange(8, 4096));
  cmd->add_flag("--force", o->render.force, "Replace a read-only output file");
  return [o] { return runThumbnail(*o); };
}

}  // namespace illum::cli
