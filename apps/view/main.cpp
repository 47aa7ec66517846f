// illum-view: `illum view` as a program of its own. The CLI runs it for `illum view ...`
// (apps/illum/main.cpp), so that the commands that open no window do not load SDL2 and the display
// and sound libraries it brings (X11, Wayland, PulseAudio: about 4 ms at every start).
#include <illum/error.h>

#include "cli_errors.h"
#include "view_command.h"

#include <iostream>
#include <string>
#include <vector>
#include <algorithm>

int main(int argc, char** argv) {
  CLI::App app{"illum view: the lighting models in a window"};
  app.name("illum");
  app.require_subcommand(1);
  const illum::cli::Command view = illum::view::addViewCommand(app);
  std::vector<std::string> args(argv + 1, argv + argc);
  args.insert(args.begin(), "view");
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "illum: error: " << illum::cli::explainParseError(e, app, "view") << "\n";
    return 2;
  }
  return illum::cli::runReportingErrors(view);
}
