// Options given by name instead of on a command line (the C++ library and the Python module):
// handed to the command's own CLI11 parser, so that they are checked by the same code and refused
// with the same messages as `illum COMMAND --NAME VALUE`.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace illum::cli {

// {"resolution", "320x240"}, {"camera_azimuth_angle", "30"}, {"edges", "true"}: a name is the
// option's long name, its dashes or underscores alike; a flag takes true or false.
using NamedOptions = std::vector<std::pair<std::string, std::string>>;

// Parses `options` with `command` (an App holding only that command's options, named `name` in
// messages), and `positional` (an input's path) as the command line's positional argument when
// given. Throws InputError with the CLI's message for an unknown option or a refused value.
void parseNamedOptions(CLI::App& command, const std::string& name, const NamedOptions& options,
                       const std::vector<std::string>& positional = {});

}  // namespace illum::cli
