// swingsim generate STUDY.yaml [--out DIR]: synthetic measurement data from a model
// (study/generate_run.h).
#include <optional>
#include <string>

#include "cli/command.h"
#include "study/generate_run.h"

namespace swingsim::cli {

namespace {

/// What `swingsim generate` was given; nullopt: not given (the default applies).
struct GenerateArguments {
  std::string study;
  std::optional<std::string> out;
};

int runGenerateCommand(const GenerateArguments& args) {
  runGenerate(args.study, args.out);
  return 0;
}

}  // namespace

Command addGenerateCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "generate", "synthetic measurement data (cylinder bench records, swing kinematics) from a model, noise and seed");
  auto a = std::make_shared<GenerateArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-bench or swing-kinematics")
      ->required()
      ->type_name("");
  addTextOption(sub, "--out", a->out, "output folder for the CSV files (default: the study's output_dir)", "DIR");
  return {sub, [a] { return runGenerateCommand(*a); }};
}

}  // namespace swingsim::cli
