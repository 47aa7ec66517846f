// The `view` subcommand of the CLI, added beside the others (commands.h).
#pragma once

#include "commands.h"

namespace illum::view {

cli::Command addViewCommand(CLI::App& app);

}  // namespace illum::view
