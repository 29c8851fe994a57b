// swingsim: swing-phase simulation and knee models for transfemoral prostheses.
// Thin main: build the command line from the registered subcommands (CLI11), run the one
// asked for, turn exceptions into messages and exit codes (0 success, 1 bad input or failed
// run, 2 usage error).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "cli/command_registry.h"
#include "core/input_error.h"

int main(int argc, char** argv) {
  using namespace swingsim::cli;
  CLI::App app{"swingsim: swing-phase simulation and knee models for transfemoral (above-knee) prostheses", "swingsim"};
  app.set_version_flag("--version", std::string("swingsim ") + SWINGSIM_VERSION);
  app.require_subcommand(0, 1);
  app.footer("'swingsim <command> --help' lists a command's options.");
  // Every subcommand with its positional (kept as given; the command checks how many) and
  // options, each stored as text and converted by the command (Arguments).
  struct Parsed {
    std::vector<std::string> positional;
  };
  std::map<std::string, Parsed> parsed;
  std::map<std::string, CLI::App*> subcommands;
  for (const auto& [name, command] : commandRegistry()) {
    CLI::App* sub = app.add_subcommand(name, command.summary);
    sub->add_option(command.positional, parsed[name].positional, command.positionalHelp);
    for (const auto& o : command.options) {
      if (o.isSwitch)
        sub->add_flag(o.flag, o.help);
      else
        sub->add_option(o.flag, o.help)->type_name("VALUE");
    }
    subcommands[name] = sub;
  }
  if (argc < 2) {
    std::printf("%s", app.help().c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;  // --help and --version exit 0; anything else is a usage error
  }
  for (const auto& [name, sub] : subcommands) {
    if (!sub->parsed()) continue;
    const Command& command = commandRegistry().at(name);
    std::map<std::string, std::string> values;
    for (const auto& o : command.options) {
      if (sub->count(o.flag) == 0) continue;
      values[o.flag] = o.isSwitch ? "" : sub->get_option(o.flag)->as<std::string>();
    }
    try {
      return command.run(Arguments(parsed[name].positional, values));
    } catch (const UsageError& e) {
      std::fprintf(stderr, "swingsim %s: %s\n\n%s", name.c_str(), e.what(), sub->help().c_str());
      return 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "swingsim: %s\n", e.what());
      return 1;
    }
  }
  std::printf("%s", app.help().c_str());
  return 2;
}
