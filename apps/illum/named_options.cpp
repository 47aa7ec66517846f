#include "named_options.h"

#include "cli_errors.h"

#include <illum/error.h>

#include <algorithm>

namespace illum::cli {

void parseNamedOptions(CLI::App& command, const std::string& name, const NamedOptions& options,
                       const std::vector<std::string>& positional) {
  std::vector<std::string> args;
  for (const auto& [key, value] : options) {
    std::string option = "--" + key;
    std::replace(option.begin(), option.end(), '_', '-');
    const CLI::Option* known = command.get_option_no_throw(option);
    if (known && known->get_expected_max() == 0) {  // a flag
      if (value == "true" || value == "1") args.push_back(option);
      else if (value != "false" && value != "0")
        throw InputError(option + ": a flag: expected true or false, got \"" + value + "\"");
      continue;
    }
    args.push_back(option);
    args.push_back(value);
  }
  if (!positional.empty()) {
    args.push_back("--");  // what follows is positional even when it starts with a dash
    args.insert(args.end(), positional.begin(), positional.end());
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  try {
    command.parse(args);
  } catch (const CLI::ParseError& e) {
    // The messages name the command as `illum NAME`, as on the command line.
    command.name(name);
    throw InputError(explainParseError(e, command, name));
  }
}

}  // namespace illum::cli
