// The command line's mistakes in illum's words: an unknown command or option names the closest
// one there is, and CLI11's own wordings ("not expected", "At Most 1 required") become the option,
// what was expected and what was given.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace illum::cli {

// Whether `first` (the first argument, not an option) is meant as an input of `illum FILE`'s
// shortcut: an existing file or folder, or what looks like a path or a pattern. A bare word that is
// neither, like "rendr", is a mistyped command: the message for it, with the closest command.
std::optional<std::string> unknownCommand(const std::string& first, const std::vector<std::string>& commands);

// Runs a command and maps what it throws to the exit status and a message on stderr: InputError
// exit 2, everything else (Error, out of memory, ...) exit 1.
int runReportingErrors(const std::function<int()>& command);

// The message for a parse error of `command` (the subcommand's name, or empty; `app` may be that
// subcommand itself).
std::string explainParseError(const CLI::ParseError& error, const CLI::App& app, const std::string& command);

}  // namespace illum::cli
