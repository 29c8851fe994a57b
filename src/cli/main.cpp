// swingsim: swing-phase simulation and knee models for transfemoral prostheses.
// Thin main: declare every subcommand on the CLI11 app, parse, run the one given, and turn
// exceptions into messages and exit codes: 0 success, 1 bad input or failed run
// (`swingsim: <message>`), 2 usage error (unknown option, missing argument, bad option value).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/command.h"

int main(int argc, char** argv) {
  using namespace swingsim::cli;
  CLI::App app{"swingsim: swing-phase simulation and knee models for transfemoral (above-knee) prostheses", "swingsim"};
  app.set_version_flag("--version", std::string("swingsim ") + SWINGSIM_VERSION);
  app.require_subcommand(0, 1);
  app.failure_message([](const CLI::App* top, const CLI::Error& e) {
    const auto given = top->get_subcommands();
    return std::string("swingsim: ") + e.what() + "\nRun '" +
           (given.empty() ? std::string("swingsim --help' for the commands")
                          : "swingsim " + given.front()->get_name() + " --help' for its options") +
           ".\n";
  });
  const std::vector<Command> commands = {addSimulateCommand(app),   addSweepCommand(app),      addCalibrateCommand(app),
                                         addFitCommand(app),        addCompareCommand(app),    addDiagnoseCommand(app),
                                         addGenerateCommand(app),   addMergeCommand(app),      addSwingsCommand(app),
                                         addImportOsimCommand(app), addExportOsimCommand(app), addTuneCommand(app),
                                         addServeCommand(app),      addPartsCommand(app)};
  // Set after adding the subcommands, which would inherit it.
  app.footer("'swingsim <command> --help' lists a command's options with their units and defaults.");
  if (argc < 2) {
    std::printf("%s", app.help().c_str());
    return 2;
  }
  // --help and --version exit 0; any other parse error is a usage error.
  const auto usageExit = [&app](const CLI::ParseError& e) { return app.exit(e) == 0 ? 0 : 2; };
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return usageExit(e);
  }
  for (const Command& command : commands) {
    if (!command.app->parsed()) continue;
    // An empty value is never meant (`--out ""` would write into the root folder).
    for (const CLI::Option* option : command.app->get_options())
      for (const std::string& value : option->results())
        if (option->get_expected_min() > 0 && value.empty())
          return usageExit(CLI::ValidationError(option->get_name(), "expected a value, got an empty string"));
    try {
      return command.run();
    } catch (const CLI::ParseError& e) {
      return usageExit(e);
    } catch (const std::bad_alloc&) {
      std::fprintf(stderr,
                   "swingsim: out of memory (a memory limit such as ulimit -v, or a container's): run with "
                   "fewer --jobs or a higher limit; nothing was written\n");
      return 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "swingsim: %s\n", e.what());
      return 1;
    }
  }
  std::printf("%s", app.help().c_str());  // options of swingsim itself but no command
  return 2;
}
