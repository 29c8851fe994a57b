#pragma once
// Subcommands register themselves here (one file per subcommand under src/cli/), so
// main() stays thin and a new command touches no shared file.
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace swingsim::cli {

using CommandFn = std::function<int(const std::vector<std::string>& args)>;

struct Command {
  std::string usage;    ///< one line: "simulate PARTICIPANT.yaml [--lowering M] ..."
  std::string summary;  ///< one sentence for `swingsim` without arguments
  CommandFn run;
};

std::map<std::string, Command>& commandRegistry();

/// Static-initialisation helper: `static Registrar reg("fit", {...});`.
struct Registrar {
  Registrar(const std::string& name, Command command) {
    commandRegistry()[name] = std::move(command);
  }
};

/// Thrown for a command-line usage error (exit code 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parsed `POSITIONAL... --flag VALUE --switch` arguments.
class Arguments {
 public:
  /// `valueFlags` take a value, `switchFlags` do not; anything else is a usage error.
  Arguments(const std::vector<std::string>& args, const std::vector<std::string>& valueFlags,
            const std::vector<std::string>& switchFlags = {});
  const std::vector<std::string>& positional() const { return positional_; }
  bool has(const std::string& flag) const;
  std::string get(const std::string& flag, const std::string& defaultValue = "") const;
  /// A flag's value as a number; usage error if it is not one.
  double getDouble(const std::string& flag, double defaultValue) const;
  int getInt(const std::string& flag, int defaultValue) const;

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
};

}  // namespace swingsim::cli
