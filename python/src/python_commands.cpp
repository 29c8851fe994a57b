// The module's functions over the package's file objects and the OpenSim commands: a
// diagnosis study loaded into a dict, any file object checked and written back as YAML,
// `swings`, `import_osim` and `export_osim`, each calling the library code the command
// line calls (src/study/), with its arguments checked against the command line's ranges.
#include "python_commands.h"

#include <pybind11/stl.h>

#include <filesystem>
#include <iterator>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_paths.h"
#include "io/trajectory_writer.h"
#include "python_objects.h"
#include "python_values.h"
#include "study/diagnosis_objects.h"
#include "study/osim_export.h"
#include "study/osim_import.h"
#include "study/swing_listing.h"

namespace py = pybind11;

namespace swingsim::python {
namespace {

/// The diagnosis study file at `path` as a dict (paths as written, relative to its folder).
py::object loadStudyDict(const py::object& pathValue) {
  const std::string path = readPathArgument(pathValue, "load_study(): path");
  return yamlTextToPython(formatDiagnosisStudyYaml(loadDiagnosisStudy(path), folderOf(path)));
}

/// `record` (a Participant, KneeModel or DiagnosisStudy) through its loader, and its YAML
/// text as the project's writer writes it for a file in `folder` (relative paths rewritten
/// to it). Raises InputError, naming the key, for what the loader refuses.
std::string formatRecord(const py::object& record, const std::string& folder) {
  if (isPackageObject(record, "Participant")) {
    const auto [text, source] = objectAsYaml(record, "participant");
    return formatParticipantYaml(parseParticipant(text, source), folder);
  }
  if (isPackageObject(record, "KneeModel")) {
    const auto [text, source] = objectAsYaml(record, "knee model");
    return formatKneeModelYaml(parseKneeModel(text, source).spec);
  }
  if (isPackageObject(record, "DiagnosisStudy")) {
    const auto [text, source] = objectAsYaml(record, "study");
    return formatDiagnosisStudyYaml(parseDiagnosisStudy(text, source), folder);
  }
  throw py::type_error(
      formatArgumentProblem("record", "expected a Participant, KneeModel or DiagnosisStudy", describePython(record)));
}

/// What `swingsim swings FILE.mot ... --json` writes, as Python objects.
py::object swings(const py::object& motion, const py::object& side, const py::object& grf,
                  const py::object& verticalForce, const py::object& thresholdN, const py::object& fallback,
                  const py::object& gait, const py::object& kneeSign) {
  SwingListRequest r;
  r.kinematics = readPathArgument(motion, "swings(): motion_path");
  r.side = readChoiceArgument(side, "swings(): side", {"r", "l"});
  if (!grf.is_none()) r.grf = readPathArgument(grf, "swings(): grf");
  if (!verticalForce.is_none()) r.verticalForce = readTextArgument(verticalForce, "swings(): vertical_force");
  r.thresholdN = readNumberArgument(thresholdN, "swings(): threshold_N", checkForceThreshold);
  r.fallbackToKinematics = readFlagArgument(fallback, "swings(): fallback_to_kinematics");
  if (!gait.is_none()) r.gait = readChoiceArgument(gait, "swings(): gait", {"walking", "running"});
  r.kneeSign = readNumberArgument(kneeSign, "swings(): knee_sign", checkKneeSign);
  Json json;
  {
    py::gil_scoped_release release;
    json = makeSwingListJson(r, listLegSwings(r));
  }
  return toPython(json);
}

/// An optional positive number argument (a mass, kg; a length, m).
std::optional<double> readOptionalPositive(const py::object& value, const std::string& where) {
  if (value.is_none()) return std::nullopt;
  return readNumberArgument(value, where, checkPositive);
}

/// `swingsim import-osim MODEL.osim` as the participant file's dict and its name.
py::tuple importOsim(const py::object& model, const py::object& side, const py::object& name, const py::object& knee,
                     const py::object& friction, const py::object& shankMass, const py::object& footMass,
                     const py::object& footLength, const py::object& height, const py::object& kneePart,
                     const py::object& pylonPart, const py::object& anklePart, const py::object& footPart,
                     const py::object& catalogue) {
  const std::string path = readPathArgument(model, "import_osim(): osim_path");
  OsimImportOptions o;
  o.side = readChoiceArgument(side, "import_osim(): side", {"r", "l"}).front();
  if (!name.is_none()) o.name = readTextArgument(name, "import_osim(): name");
  o.kneeModelPath = knee.is_none() ? defaultImportKneePath() : readPathArgument(knee, "import_osim(): knee");
  o.kneeFriction = readNumberArgument(friction, "import_osim(): knee_friction_Nm", checkKneeFriction);
  o.shankMass = readOptionalPositive(shankMass, "import_osim(): shank_mass_kg");
  o.footMass = readOptionalPositive(footMass, "import_osim(): foot_mass_kg");
  o.footLength = readOptionalPositive(footLength, "import_osim(): foot_length_m");
  o.height = readOptionalPositive(height, "import_osim(): height_m");
  ImportPartNames parts;
  const py::object* named[] = {&kneePart, &pylonPart, &anklePart, &footPart};  // in kPartCategories' order
  for (std::size_t i = 0; i < std::size(kPartCategories); ++i)
    if (!named[i]->is_none()) parts.of(kPartCategories[i]) = readTextArgument(*named[i], "import_osim(): a part's id");
  if (!catalogue.is_none()) parts.catalogue = readPathArgument(catalogue, "import_osim(): parts_catalogue");
  o.parts = chooseImportParts(parts, [](const std::string& key) {
    return "import_osim(): " + (key == "catalogue" ? std::string("parts_catalogue") : key + "_part");
  });
  ImportedParticipantYaml imported;
  {
    py::gil_scoped_release release;
    imported = importOsimParticipant(path, o, ".");
  }
  return py::make_tuple(yamlTextToPython(imported.text), imported.name);
}

/// `swingsim export-osim PARTICIPANT --side S --lowering M [--add-mass KG@M]` written to the
/// file `path`; returns it.
std::string exportOsim(const py::object& participant, const py::object& pathValue, const py::object& loweringValue,
                       const py::object& side, const py::object& addedMass, const py::object& addedBelow) {
  const std::string path = readPathArgument(pathValue, "export_osim(): path");
  OsimExportOptions options;
  options.side = readChoiceArgument(side, "export_osim(): side", {"r", "l"}).front();
  options.lowering = readNumberArgument(loweringValue, "export_osim(): lowering_m", checkLowering);
  options.added = readAddedMassArguments(addedMass, addedBelow, "export_osim()");
  const Participant p = readParticipant(participant, "export_osim");
  const KneeModel knee = readKnee(py::none(), p, "export_osim");
  // An edited Participant's messages name "ORIGIN (edited in Python)": its origin file is an input too.
  const std::string origin = isPathArgument(participant) ? p.path : participant.attr("origin").cast<std::string>();
  checkOutputsAreNotInputs({{"participant", origin}, {"participant: knee_model", p.kneeModelPath}}, {{"path", path}});
  py::gil_scoped_release release;
  const std::string sto = makeTrajectoryFileStem(p.name, options.lowering) + ".sto";
  writeFileAtomic(path, formatParticipantOsim(p, knee, options, sto));
  return path;
}

}  // namespace

void addRecordFunctions(py::module_& m) {
  m.def("load_study_dict", &loadStudyDict, py::arg("path"));
  m.def("format_record", &formatRecord, py::arg("record"), py::arg("folder"));
  m.def("swings", &swings, py::arg("motion_path"), py::arg("side") = "r", py::arg("grf") = py::none(),
        py::arg("vertical_force") = py::none(), py::arg("threshold_N") = 20.0,
        py::arg("fallback_to_kinematics") = false, py::arg("gait") = py::none(), py::arg("knee_sign") = -1.0);
  m.def("import_osim", &importOsim, py::arg("osim_path"), py::arg("side") = "r", py::arg("name") = py::none(),
        py::arg("knee") = py::none(), py::arg("knee_friction_Nm") = 0.0, py::arg("shank_mass_kg") = py::none(),
        py::arg("foot_mass_kg") = py::none(), py::arg("foot_length_m") = py::none(), py::arg("height_m") = py::none(),
        py::arg("knee_part") = py::none(), py::arg("pylon_part") = py::none(), py::arg("ankle_part") = py::none(),
        py::arg("foot_part") = py::none(), py::arg("parts_catalogue") = py::none());
  m.def("export_osim", &exportOsim, py::arg("participant"), py::arg("path"), py::arg("lowering_m") = 0.0,
        py::arg("side") = "r", py::arg("added_mass_kg") = py::none(), py::arg("added_mass_below_knee_m") = py::none());
}

}  // namespace swingsim::python
