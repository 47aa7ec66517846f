// `illum view [FILES...]`: the lighting models in a window (view_window.h).
#include "view_command.h"

#include "view_window.h"

#include <memory>

namespace illum::view {

cli::Command addViewCommand(CLI::App& app) {
  struct Options {
    cli::SceneOptions scene;
    std::vector<std::string> inputs;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("view", cli::kViewSummary);
  cmd->footer(
      "Keys as f3d's: drag to turn, right drag or wheel to zoom, middle drag to pan, click a pixel to\n"
      "see its equation, H for every key. Needs a display; without one, use illum render.");
  cli::addSceneOptions(*cmd, o->scene, &o->inputs);
  return [o] { return runViewer(o->inputs, o->scene); };
}

}  // namespace illum::view
