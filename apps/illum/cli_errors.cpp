#include "cli_errors.h"

#include "cli_values.h"

#include <illum/error.h>

#include <filesystem>
#include <iostream>
#include <new>
#include <regex>
#include <sstream>

namespace illum::cli {
namespace {

// What people type, from other tools (f3d, Blender, ImageMagick), and what illum calls it.
const std::vector<std::pair<std::string, std::string>> kOptionSynonyms = {
    {"--size", "--resolution"},          {"--azimuth", "--camera-azimuth-angle"},
    {"--elevation", "--camera-elevation-angle"}, {"--zoom", "--camera-zoom-factor"},
    {"--fov", "--camera-view-angle"},    {"--spp", "--samples"},
    {"--msaa", "--samples"},             {"--aa", "--samples"},
    {"--bg", "--background-color"},      {"--background-colour", "--background-color"},
    {"--colour", "--color"},             {"--out", "--output"},
    {"--threads-count", "--threads"},    {"--light", "--light-intensity"},
};

// Every name of `command`'s options, with their dashes (`app` itself when it is that command).
std::vector<std::string> optionNames(const CLI::App& app, const std::string& command) {
  const CLI::App* sub = command.empty() || app.get_name() == command ? &app : app.get_subcommand(command);
  std::vector<std::string> names;
  for (const CLI::Option* option : sub->get_options()) {
    for (const std::string& l : option->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : option->get_snames()) names.push_back("-" + s);
  }
  return names;
}

}  // namespace

std::optional<std::string> unknownCommand(const std::string& first, const std::vector<std::string>& commands) {
  std::error_code ec;
  if (first == "-" || std::filesystem::exists(first, ec) || first.find_first_of("/.*?[\\~") != std::string::npos)
    return std::nullopt;
  std::string list;
  for (std::size_t i = 0; i < commands.size(); ++i) list += (i ? ", " : "") + commands[i];
  const std::optional<std::string> meant = closestName(first, commands);
  return first + ": no such command or file" + (meant ? "; did you mean " + *meant + "?" : "") + " (commands: " + list +
         "; `illum FILE` renders a scene or model file)";
}

int runReportingErrors(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    std::cerr << "illum: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "illum: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "illum: error: " << e.what() << "\n";
    return 1;
  }
}

std::string explainParseError(const CLI::ParseError& error, const CLI::App& app, const std::string& command) {
  const std::string what = error.what(), where = command.empty() ? "illum" : "illum " + command;
  std::smatch m;
  // "The following argument(s) was/were not expected: A B": CLI11 lists them last first.
  if (dynamic_cast<const CLI::ExtrasError*>(&error) && std::regex_search(what, m, std::regex(R"(expected: (.*)$)"))) {
    std::vector<std::string> extras;
    std::istringstream in(m[1].str());
    for (std::string word; in >> word;) extras.insert(extras.begin(), word);
    for (const std::string& extra : extras)
      if (extra.size() > 1 && extra[0] == '-') {
        const std::string name = extra.substr(0, extra.find('='));
        const std::optional<std::string> meant = closestName(name, optionNames(app, command), kOptionSynonyms);
        return name + ": not an option of " + where + (meant ? "; did you mean " + *meant + "?" : "") + " (" + where +
               " --help lists them)";
      }
    return "\"" + extras.front() + "\": not expected here (" + where + " --help says what " + where + " takes)";
  }
  if (what == "A subcommand is required")
    return "expected a command (eval, render, bench, compare, history, view, thumbnail or exercise) or a file to render (illum --help)";
  if (std::regex_search(what, m, std::regex(R"(^(\S+): At Most (\d+) required but received (\d+))")))
    return m[1].str() + ": given " + m[3].str() + " times; expected " + (m[2].str() == "1" ? "once" : "at most " + m[2].str() + " times");
  if (std::regex_search(what, m, std::regex(R"(^(\S+): Value (.*) not in range (.*) to (.*)$)")))
    return m[1].str() + ": expected a value in [" + m[3].str() + ", " + m[4].str() + "], got \"" + m[2].str() + "\"";
  if (std::regex_search(what, m, std::regex(R"(Could not convert: (\S+) = (.*)$)")))
    return m[1].str() + ": expected a number, got \"" + m[2].str() + "\"";
  return what;
}

}  // namespace illum::cli
