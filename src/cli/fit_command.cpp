// swingsim fit STUDY.yaml [--out DIR] [--json FILE]: fit Mauch cylinder models to bench
// data and validate them on held-out conditions (Chien 2014 procedure). All inputs are read
// and checked before anything is written.
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command.h"
#include "core/output_files.h"
#include "core/staged_writer.h"
#include "report/cylinder_fit_report.h"
#include "study/cylinder_fit_run.h"
#include "study/cylinder_study.h"

namespace swingsim::cli {

namespace {

/// What `swingsim fit` was given; nullopt: not given (the default applies).
struct FitArguments {
  std::string study;
  std::optional<std::string> out, json;
};

int runFit(const FitArguments& args, const std::string& command) {
  const CylinderFitStudy study = loadCylinderFitStudy(args.study);
  const std::string outDir = chooseStudyOutputFolder(args.out, study.name, study.path);
  std::vector<CommandFile> outputs = listRunOutputs(outDir, {"report.md"}, args.json);
  checkOutputsAreNotInputs({{"STUDY.yaml", args.study}}, outputs);
  const CylinderFitRun run = runCylinderFits(study.models, study.train, study.validate, study.fitSwitches);
  const std::vector<ModelEvaluation>& results = run.models;

  std::printf("%s", formatFitTable(results).c_str());
  for (const auto& r : results)
    for (const auto& w : r.fit.warnings)
      std::fprintf(stderr, "swingsim fit: warning: %s: %s\n", r.name.c_str(), w.c_str());

  // The report, its figures and --json as one set: the folder holds this run or the one before.
  StagedOutput staged(outDir, OutputSetKind::kWholeRun);
  stageFolderWriter(staged, [&](const std::string& folder) {
    writeFitReport(folder, study.name, command, results, study.plotSeconds);
  });
  if (args.json) staged.addBeside(*args.json, formatFitJson(results));
  staged.commit();
  std::printf("report: %s/report.md\n", outDir.c_str());
  return 0;
}

}  // namespace

Command addFitCommand(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("fit", "fit Mauch cylinder models to bench data and validate them on held-out files");
  auto a = std::make_shared<FitArguments>();
  sub->add_option("STUDY.yaml", a->study, "study of kind cylinder-fit")->required()->type_name("");
  addStudyOutOption(sub, a->out);
  addJsonOption(sub, a->json);
  return {sub, [a, sub] { return runFit(*a, formatCommandLine(*sub)); }};
}

}  // namespace swingsim::cli
