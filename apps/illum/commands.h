// The CLI's commands, one file each. Each adds its subcommand and returns the function that runs it.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace illum::cli {

using Command = std::function<int()>;

Command addEvalCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addHistoryCommand(CLI::App& app);
Command addThumbnailCommand(CLI::App& app);
Command addExerciseCommand(CLI::App& app);

}  // namespace illum::cli
