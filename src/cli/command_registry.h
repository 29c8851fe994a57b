#pragma once
// Subcommands register themselves here (one file per subcommand under src/cli/), so
// main() stays thin and a new command touches no shared file. Each command declares its
// positional argument and its options with their help (unit and default); main() builds the
// command line from these with CLI11, so `swingsim SUB --help` lists every option.
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace swingsim::cli {

/// Parsed arguments of one subcommand: its positionals and the options the user gave.
class Arguments {
 public:
  Arguments(std::vector<std::string> positional, std::map<std::string, std::string> values)
      : positional_(std::move(positional)), values_(std::move(values)) {}
  const std::vector<std::string>& positional() const { return positional_; }
  /// Whether the user gave `flag` ("--out").
  bool has(const std::string& flag) const { return values_.count(flag) > 0; }
  std::string get(const std::string& flag, const std::string& defaultValue = "") const;
  /// A flag's value as a finite number; usage error if it is not one.
  double getDouble(const std::string& flag, double defaultValue) const;
  /// A flag's value as a whole number; usage error if it is not one.
  int getInt(const std::string& flag, int defaultValue) const;
  /// The command line as given, for reports: "swingsim NAME POSITIONAL... --flag VALUE ...".
  std::string commandLine(const std::string& name) const;

 private:
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
};

/// One option of a command: "--out" with its help (say the unit and the default).
struct OptionSpec {
  std::string flag;
  std::string help;
  bool isSwitch = false;  ///< takes no value (e.g. --dry-run)
};

struct Command {
  std::string summary;         ///< one sentence for `swingsim` without arguments
  std::string positional;      ///< name of the positional argument: "STUDY.yaml"
  std::string positionalHelp;  ///< what it is
  std::vector<OptionSpec> options;
  std::function<int(const Arguments&)> run;
};

std::map<std::string, Command>& commandRegistry();

/// Static-initialisation helper: `static Registrar reg("fit", {...});`.
struct Registrar {
  Registrar(const std::string& name, Command command) { commandRegistry()[name] = std::move(command); }
};

/// Thrown for a command-line usage error (exit code 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace swingsim::cli
