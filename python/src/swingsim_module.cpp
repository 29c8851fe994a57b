// The Python module `swingsim._swingsim` (wrapped by swingsim/__init__.py): loading
// participants and knee models into editable dicts, one swing, the sweep, tuning, fit and
// diagnosis studies (a diagnosis from a path or a study object with records in memory),
// each calling the same library functions as the command line, with the GIL released while
// they run; file objects, swings and the .osim import/export are in python_commands.cpp. Bad input raises
// swingsim.InputError (a ValueError) with the CLI's `file:line: key: ...` message; a failed run raises
// swingsim.RunError (a RuntimeError). Arguments are checked first, against the command line's ranges
// (study/run_arguments.h): a wrong type raises TypeError, a value out of range InputError, each naming the argument.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // std::optional arguments

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/input_error.h"
#include "core/output_files.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/trajectory_writer.h"
#include "python_commands.h"
#include "python_objects.h"
#include "python_values.h"
#include "report/cylinder_fit_report.h"
#include "report/diagnosis_report.h"
#include "report/sweep_report.h"
#include "report/swing_json.h"
#include "study/cylinder_fit_run.h"
#include "study/cylinder_study.h"
#include "study/diagnosis_objects.h"
#include "study/diagnosis_study.h"
#include "study/run_arguments.h"
#include "study/simulate_run.h"
#include "study/sweep_run.h"
#include "study/sweep_study.h"
#include "study/tuning_run.h"

namespace py = pybind11;

namespace swingsim::python {
namespace {

/// The participant file at `path` as a dict in file units.
py::object loadParticipantDict(const std::string& path) {
  const Participant p = loadParticipant(path);
  return yamlTextToPython(formatParticipantYaml(p, folderOf(path)));
}

/// The knee model file at `path` as a dict in file units, with its `name` always there.
py::object loadKneeDict(const std::string& path) {
  const KneeModel model = loadKneeModel(path);
  KneeModelSpec spec = model.spec;
  if (spec.name.empty()) spec.name = model.name;
  return yamlTextToPython(formatKneeModelYaml(spec));
}

py::dict trajectoryArrays(const SwingTrajectory& trajectory) {
  const TrajectoryColumns columns = calcTrajectoryColumns(trajectory);
  py::dict arrays;
  for (std::size_t i = 0; i < columns.names.size(); ++i)
    arrays[py::str(columns.names[i])] = py::array_t<double>(columns.values[i].size(), columns.values[i].data());
  return arrays;
}

/// The integrator and its accuracy as simulate's --integrator and --accuracy (makeSimulateOptions).
SwingOptions readSwingOptionArguments(const py::object& integrator, const py::object& accuracy) {
  std::optional<std::string> key;
  std::optional<double> value;
  if (!integrator.is_none()) key = readChoiceArgument(integrator, "simulate(): integrator", integratorKeys());
  if (!accuracy.is_none()) value = readNumberArgument(accuracy, "simulate(): accuracy", checkAccuracy);
  return makeSimulateOptions(key, value);
}

/// One swing as `swingsim simulate --json` describes it, plus "knee_model" and the
/// trajectory's columns as numpy arrays under "trajectory".
py::dict simulate(const py::object& participant, const py::object& loweringValue, const py::object& knee,
                  const py::object& addedMass, const py::object& addedBelow, const py::object& integrator,
                  const py::object& accuracy) {
  const double lowering = readNumberArgument(loweringValue, "simulate(): lowering_m", checkLowering);
  const AddedMass added = readAddedMassArguments(addedMass, addedBelow, "simulate()").value_or(AddedMass{});
  const SwingOptions options = readSwingOptionArguments(integrator, accuracy);
  Participant loaded = readParticipant(participant, "simulate");
  const KneeModel model = readKnee(knee, loaded, "simulate");
  std::optional<SimulateRun> run;
  {
    py::gil_scoped_release release;
    run = runSimulate(std::move(loaded), model, lowering, added, options);
  }
  py::dict out = toPython(makeSimulateJson(run->setup, run->result));
  out["knee_model"] = model.name;
  out["trajectory"] = trajectoryArrays(run->result.trajectory);
  return out;
}

/// The sweep study's inputs against the files a run writes into `out`: refused before any swing.
void checkSweepOutputs(const SweepStudy& study, const std::string& out) {
  std::vector<CommandFile> inputs = {{"study_path", study.path}};
  for (const Participant& p : study.participants)
    if (!p.path.empty()) inputs.push_back({"study_path: participant " + p.name, p.path});
  for (const auto& [path, model] : study.kneeModels) inputs.push_back({"study_path: a knee model", path});
  checkOutputsAreNotInputs(inputs, listFolderFiles("sweep(): out", out, kSweepReportFiles));
}

/// The content of `swingsim sweep STUDY --json` ([--uncertainty N] [--seed S]) as Python
/// objects; with `out`, the command's report, figures and CSV are written there too (one
/// staged set). Ctrl-C stops it between swings and raises KeyboardInterrupt.
py::object sweep(const py::object& studyPath, const py::object& uncertaintyValue, const py::object& seedValue,
                 const py::object& jobsValue, const py::object& outValue) {
  // Every argument checked before the study is read or anything allocated.
  const std::string path = readPathArgument(studyPath, "sweep(): study_path");
  const long long uncertainty = readWholeArgument(uncertaintyValue, "sweep(): uncertainty", uncertaintyOrNoneRange());
  std::optional<long long> seed;
  if (!seedValue.is_none()) seed = readWholeArgument(seedValue, "sweep(): seed", seedRange());
  const int jobs = static_cast<int>(readWholeArgument(jobsValue, "sweep(): jobs", jobsRange()));
  std::optional<std::string> out;
  if (!outValue.is_none()) out = readPathArgument(outValue, "sweep(): out");
  SweepStudy study = loadSweepStudy(path);
  if (out) checkSweepOutputs(study, *out);
  applyUncertaintyArguments(study, uncertainty > 0 ? std::optional<int>(static_cast<int>(uncertainty)) : std::nullopt,
                            seed ? std::optional<int>(static_cast<int>(*seed)) : std::nullopt,
                            {"sweep(): seed", "uncertainty=N", "seed=" + std::to_string(seed.value_or(0))});
  volatile bool stop = false;
  // Called from the thread that runs the sweep (this one): Python's signal handlers run
  // there, so Ctrl-C sets the stop flag.
  auto checkSignals = [&stop] {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) stop = true;
  };
  SweepRunControl control;
  control.stop = &stop;
  control.poll = checkSignals;
  std::string json;
  {
    py::gil_scoped_release release;
    SweepRun run(std::move(study), jobs, control);
    run.calibrate();
    run.planUncertainty("");  // no partial file: a stopped analysis raises KeyboardInterrupt
    if (run.sweep() && run.runUncertainty()) {
      json = run.formatJson();
      if (out) run.writeOutputs(*out, std::nullopt);
    }
  }
  if (stop) throw py::error_already_set();
  return toPython(Json::parse(json));
}

/// The content of `swingsim tune STUDY --json` as Python objects, plus the tuned knee model
/// file's text under "tuned_knee_yaml". With `out`, the command's files are written there too
/// (one staged set). Ctrl-C stops it between swings and raises KeyboardInterrupt.
py::object tune(const py::object& studyPath, const py::object& jobsValue, const py::object& outValue) {
  const std::string path = readPathArgument(studyPath, "tune(): study_path");
  const int jobs = static_cast<int>(readWholeArgument(jobsValue, "tune(): jobs", jobsRange()));
  std::optional<std::string> out;
  if (!outValue.is_none()) out = readPathArgument(outValue, "tune(): out");
  const TuningStudy study = loadTuningStudy(path);
  if (out)
    checkOutputsAreNotInputs({{"study_path", path},
                              {"study_path: participant", study.participantPath},
                              {"study_path: knee_model", study.kneeModelPath}},
                             listFolderFiles("tune(): out", *out, kTuningOutputFiles));
  volatile bool stop = false;
  SweepRunControl control;
  control.stop = &stop;
  control.poll = [&stop] {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) stop = true;
  };
  std::string json, knee;
  {
    py::gil_scoped_release release;
    const TuningRun run = runTuningStudy(study, jobs, control);
    if (!run.result.interrupted) {
      const std::string kneeFile = out ? *out + "/tuned-knee.yaml" : "";
      json = formatTuningRunJson(run, kneeFile);
      knee = formatKneeModelYaml(run.tunedKnee.spec);
      if (out) writeTuningOutputs(run, *out, std::nullopt, "swingsim.tune(" + path + ")");
    }
  }
  if (stop) throw py::error_already_set();
  py::dict result = toPython(Json::parse(json)).cast<py::dict>();
  result["tuned_knee_yaml"] = knee;
  return result;
}

/// The content of `swingsim fit STUDY --json`: each Mauch model's coefficients and its
/// ME / RMSE / R^2 per bench file.
py::object fit(const py::object& studyPath) {
  const CylinderFitStudy study = loadCylinderFitStudy(readPathArgument(studyPath, "fit(): study_path"));
  std::string json;
  {
    py::gil_scoped_release release;
    const CylinderFitRun run = runCylinderFits(study.models, study.train, study.validate, study.fitSwitches);
    json = formatFitJson(run.models);
  }
  return toPython(Json::parse(json));
}

/// The content of `swingsim compare STUDY --json`: the base model refitted on the training
/// files, metrics overall and per phase.
py::object compare(const py::object& studyPath) {
  const DiagnosisStudy study = loadDiagnosisStudy(readPathArgument(studyPath, "compare(): study_path"));
  Json json;
  {
    py::gil_scoped_release release;
    const auto plant = loadDiagnosisPlant(study, 1);  // as the CLI's compare
    const BaselineComparison b = compareBaseline(*plant, study.settings.whitenessLags);
    json = makeComparisonJson(fileStem(study.baseModelPath), b.comparison);
    json["warnings"] = plant->warnings();
  }
  return toPython(json);
}

/// Each record's measured and model series (numpy arrays), before and after the diagnosis.
py::list comparisonSeries(const Comparison& before, const Comparison& after) {
  py::list out;
  const auto array = [](const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); };
  for (std::size_t i = 0; i < before.records.size() && i < after.records.size(); ++i) {
    const RecordComparison& b = before.records[i];
    py::dict d;
    d["name"] = b.stem;
    d["training"] = b.training;
    d["quantity"] = before.quantity;
    d["unit"] = before.unit;
    d["time_s"] = array(b.time);
    d["measured"] = array(b.measured);
    d["baseline"] = array(b.predicted);
    d["diagnosed"] = array(after.records[i].predicted);
    out.append(d);
  }
  return out;
}

/// The records a study built in Python gives in memory: name -> CSV text of the record
/// (swingsim.SwingRecord.to_csv), read as a record file is, named by the study and the entry.
std::map<std::string, SwingRecord> readGivenRecords(const py::dict& records, const std::string& source) {
  std::map<std::string, SwingRecord> out;
  for (const auto& [name, csv] : records) {
    const std::string key = name.cast<std::string>();
    out[key] = parseSwingRecordCsv(csv.cast<std::string>(), source + ": record " + key);
  }
  return out;
}

/// The study's plant maker: from a path as the command line reads it, or from a
/// DiagnosisStudy object with the participant, knee model and records given in memory.
std::function<std::unique_ptr<DiagnosisPlant>(const DiagnosisRowLimit*)> readStudy(const py::object& studyValue,
                                                                                   const py::object& participant,
                                                                                   const py::object& knee,
                                                                                   const py::dict& records,
                                                                                   DiagnosisStudy& study) {
  if (isPathArgument(studyValue)) {
    study = loadDiagnosisStudy(readPathArgument(studyValue, "diagnose(): study"));
    return [&study](const DiagnosisRowLimit* limit) {
      return loadDiagnosisPlant(study, 8, limit);
    };  // as the CLI's diagnose
  }
  if (!isPackageObject(studyValue, "DiagnosisStudy"))
    throw py::type_error(formatArgumentProblem("diagnose(): study", "expected a path or a swingsim.DiagnosisStudy",
                                               describePython(studyValue)));
  const auto [text, source] = objectAsYaml(studyValue, "study");
  study = parseDiagnosisStudy(text, source);
  if (participant.is_none() && knee.is_none() && records.empty())
    return [&study](const DiagnosisRowLimit* limit) { return loadDiagnosisPlant(study, 8, limit); };
  auto objects = std::make_shared<SwingStudyObjects>();
  if (!participant.is_none()) objects->participant = readParticipant(participant, "diagnose");
  if (!knee.is_none()) objects->baseModel = readKnee(knee, Participant{}, "diagnose");
  objects->records = readGivenRecords(records, source);
  return [&study, objects](const DiagnosisRowLimit* limit) {
    return makeSwingDiagnosisPlant(study, std::move(*objects), limit);
  };
}

/// The content of `swingsim diagnose STUDY --json`: candidate effects ranked, the accepted
/// ones, the error before and after; plus each record's series under "series".
py::object diagnose(const py::object& studyValue, const py::object& maxRowsValue, const py::object& participant,
                    const py::object& knee, const py::dict& records) {
  DiagnosisRowLimit limit;  // maxRows 0: the plant's default, as the CLI's diagnose
  if (!maxRowsValue.is_none())
    limit.maxRows = static_cast<std::uint64_t>(readWholeArgument(maxRowsValue, "diagnose(): max_rows", maxRowsRange()));
  DiagnosisStudy study;
  const auto makePlant = readStudy(studyValue, participant, knee, records, study);
  // Ctrl-C: Python's signal handler runs before the next candidate is scored (on this thread),
  // and its KeyboardInterrupt ends the diagnosis; nothing is written.
  struct Interrupted {};
  const DiagnosisProgress checkSignals = [](int, int, int) {
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};
  };
  Json json;
  std::optional<Comparison> before, after;
  try {
    py::gil_scoped_release release;
    const auto plant = makePlant(&limit);  // size printed, limit held
    const Diagnosis dg = runDiagnosis(*plant, study.settings, checkSignals);
    before = plant->compare(*dg.baseline.model);
    after = plant->compare(*dg.final.model);
    json = makeDiagnoseJson(dg, *before, *after, plant->compareHeldBack(*dg.baseline.model),
                            plant->compareHeldBack(*dg.final.model));
  } catch (const Interrupted&) {
    throw py::error_already_set();  // the KeyboardInterrupt PyErr_CheckSignals set
  }
  py::dict result = toPython(json).cast<py::dict>();
  result["series"] = comparisonSeries(*before, *after);
  return std::move(result);
}

}  // namespace
}  // namespace swingsim::python

PYBIND11_MODULE(_swingsim, m) {
  using namespace swingsim;
  m.doc() = "swingsim's C++ core; use the swingsim package (swingsim/__init__.py)";
  static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<RunError> runError(m, "RunError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(inputError.ptr(), e.what());
    } catch (const RunError& e) {
      PyErr_SetString(runError.ptr(), e.what());
    }
  });
  m.def(
      "load_participant_dict",
      [](const py::object& path) {
        return python::loadParticipantDict(python::readPathArgument(path, "load_participant(): path"));
      },
      py::arg("path"));
  m.def(
      "load_knee_dict",
      [](const py::object& path) { return python::loadKneeDict(python::readPathArgument(path, "load_knee(): path")); },
      py::arg("path"));
  m.def("simulate", &python::simulate, py::arg("participant"), py::arg("lowering_m") = 0.0,
        py::arg("knee") = py::none(), py::arg("added_mass_kg") = py::none(),
        py::arg("added_mass_below_knee_m") = py::none(), py::arg("integrator") = py::none(),
        py::arg("accuracy") = py::none());
  m.def("sweep", &python::sweep, py::arg("study_path"), py::arg("uncertainty") = 0, py::arg("seed") = py::none(),
        py::arg("jobs") = 0, py::arg("out") = py::none());
  m.def("fit", &python::fit, py::arg("study_path"));
  m.def("tune", &python::tune, py::arg("study_path"), py::arg("jobs") = 0, py::arg("out") = py::none());
  m.def("compare", &python::compare, py::arg("study_path"));
  m.def("diagnose", &python::diagnose, py::arg("study"), py::arg("max_rows") = py::none(),
        py::arg("participant") = py::none(), py::arg("knee") = py::none(), py::arg("records") = py::dict());
  python::addRecordFunctions(m);
}
