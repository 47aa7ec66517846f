// The CLI's commands, one file each. Each adds its subcommand and returns the function that runs it.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace illum::cli {

using Command = std::function<int()>;

// What `illum view` does, in `illum --help`'s list and its own help (the viewer is its own program,
// illum-view, which `illum view` runs).
inline constexpr const char* kViewSummary =
    "Show scene or model files (none: the built-in scene) in a window to turn, light and probe (docs/view.md)";

Command addEvalCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addHistoryCommand(CLI::App& app);
Command addThumbnailCommand(CLI::App& app);
Command addExerciseCommand(CLI::App& app);

}  // namespace illum::cli
