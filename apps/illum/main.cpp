// illum: the classic local lighting models, computed and rendered exactly, on the CPU.
#include <illum/error.h>

#include "cli_errors.h"
#include "commands.h"

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <unistd.h>

namespace {

// `illum view ...` is the viewer's own program, beside this one: run in this process's place.
int runViewer(const std::vector<std::string>& args) {
  std::error_code ec;
  const std::filesystem::path viewer = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "illum-view";
  std::vector<char*> argv{const_cast<char*>("illum-view")};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(viewer.c_str(), argv.data());
  std::cerr << "illum: error: view: cannot run the viewer " << viewer.string() << ": " << std::strerror(errno)
            << " (it is installed beside illum)\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"illum: the lighting models of computer graphics, from Wylie (1967) to Kajiya (1986), rendered exactly on the CPU"};
  app.name("illum");
  app.require_subcommand(1);
  app.set_version_flag("--version", "illum 0.1.0");
  const illum::cli::Command eval = illum::cli::addEvalCommand(app);
  const illum::cli::Command render = illum::cli::addRenderCommand(app);
  const illum::cli::Command bench = illum::cli::addBenchCommand(app);
  const illum::cli::Command compare = illum::cli::addCompareCommand(app);
  const illum::cli::Command history = illum::cli::addHistoryCommand(app);
  app.add_subcommand("view", illum::cli::kViewSummary)->allow_extras();  // run by runViewer
  const illum::cli::Command thumbnail = illum::cli::addThumbnailCommand(app);
  const illum::cli::Command exercise = illum::cli::addExerciseCommand(app);

  // f3d's habit: `illum model.glb` means `illum render model.glb`; a bare word that names no file
  // is a mistyped command, never an input.
  const std::vector<std::string> commands = {"eval", "render", "bench", "compare", "history", "view", "thumbnail", "exercise"};
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0] == "view") return runViewer({args.begin() + 1, args.end()});
  if (!args.empty() && std::find(commands.begin(), commands.end(), args[0]) == commands.end() && !args[0].empty() &&
      args[0][0] != '-') {
    if (const auto message = illum::cli::unknownCommand(args[0], commands)) {
      std::cerr << "illum: error: " << *message << "\n";
      return 2;
    }
    args.insert(args.begin(), "render");
  }
  const auto command = std::find_if(args.begin(), args.end(), [&](const std::string& a) {
    return std::find(commands.begin(), commands.end(), a) != commands.end();
  });
  const std::string commandName = command == args.end() ? "" : *command;
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first

  try {
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "illum: error: " << illum::cli::explainParseError(e, app, commandName) << "\n";
    return 2;
  }

  return illum::cli::runReportingErrors([&] {
    if (app.got_subcommand("eval")) return eval();
    if (app.got_subcommand("bench")) return bench();
    if (app.got_subcommand("compare")) return compare();
    if (app.got_subcommand("history")) return history();
    if (app.got_subcommand("thumbnail")) return thumbnail();
    if (app.got_subcommand("exercise")) return exercise();
    return render();
  });
}
