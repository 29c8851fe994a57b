// swingsim: swing-phase simulation and knee models for transfemoral prostheses.
// Thin main: find the subcommand, run it, turn exceptions into messages and exit codes
// (0 success, 1 bad input or failed run, 2 usage error).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/command_registry.h"
#include "core/input_error.h"

namespace {

void printUsage(std::FILE* to) {
  std::fprintf(to, "usage: swingsim <command> [arguments]\n\ncommands:\n");
  for (const auto& [name, command] : swingsim::cli::commandRegistry()) {
    std::fprintf(to, "  %-10s %s\n", name.c_str(), command.summary.c_str());
  }
  std::fprintf(to, "\n'swingsim <command> --help' shows a command's options.\n");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace swingsim::cli;
  if (argc < 2) {
    printUsage(stdout);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    printUsage(stdout);
    return 0;
  }
  auto& registry = commandRegistry();
  auto it = registry.find(name);
  if (it == registry.end()) {
    std::fprintf(stderr, "swingsim: unknown command '%s'\n\n", name.c_str());
    printUsage(stderr);
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::printf("usage: swingsim %s\n%s\n", it->second.usage.c_str(), it->second.summary.c_str());
      return 0;
    }
  }
  try {
    return it->second.run(args);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "swingsim %s: %s\nusage: swingsim %s\n", name.c_str(), e.what(),
                 it->second.usage.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swingsim: %s\n", e.what());
    return 1;
  }
}
