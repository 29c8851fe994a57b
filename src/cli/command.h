#pragma once
// The subcommands of `swingsim`. Each src/cli/*_command.cpp declares its subcommand on the
// CLI11 app: the positional argument and every option, with help that gives the unit and
// the default, and checks that make a bad value a usage error while parsing. It returns the
// work to run once the whole command line has parsed. main() adds every command, parses, runs
// the one given and turns exceptions into messages and exit codes.
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/output_paths.h"  // chooseStudyOutputFolder
#include "study/sweep_run.h"    // kSweepReportFiles

namespace swingsim::cli {

/// A declared subcommand and its work. `run` returns the exit code; it throws InputError,
/// RunError or another std::exception for a bad input or a failed run (exit 1), and
/// CLI::ParseError for a usage error that needs more than one option to see (exit 2).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command addSimulateCommand(CLI::App& app);
Command addSweepCommand(CLI::App& app);
Command addCalibrateCommand(CLI::App& app);
Command addFitCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addDiagnoseCommand(CLI::App& app);
Command addGenerateCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addSwingsCommand(CLI::App& app);
Command addImportOsimCommand(CLI::App& app);
Command addExportOsimCommand(CLI::App& app);
Command addTuneCommand(CLI::App& app);
Command addServeCommand(CLI::App& app);
Command addPartsCommand(CLI::App& app);

/// Declares `--flag VALUE` stored in `value` (left unset unless given), shown as `typeName`
/// in --help. `value` must outlive the parse (a member of the command's argument struct).
CLI::Option* addTextOption(CLI::App* sub, const std::string& flag, std::optional<std::string>& value,
                           const std::string& help, const std::string& typeName);
/// `--json FILE`, the same for every command that writes its result as JSON.
CLI::Option* addJsonOption(CLI::App* sub, std::optional<std::string>& json);
/// `--out DIR` of the study commands: default out/<study name>/.
CLI::Option* addStudyOutOption(CLI::App* sub, std::optional<std::string>& out);

/// The data and report files a sweep or a cohort run writes into --out: study/sweep_run.h.
using swingsim::kSweepReportFiles;

/// What a run writes, for checkOutputsAreNotInputs: the files `names` in `folder` (named by
/// "--out"; none while `folder` is "", a default folder not yet known) and `json` (--json).
std::vector<CommandFile> listRunOutputs(const std::string& folder, const std::vector<std::string>& names,
                                        const std::optional<std::string>& json);

/// The command line as parsed, for reports: "swingsim fit STUDY.yaml --out DIR --json FILE"
/// (the positionals, then each option given, in the order the command declares them).
std::string formatCommandLine(const CLI::App& command);

}  // namespace swingsim::cli
