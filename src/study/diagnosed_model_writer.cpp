#include "study/diagnosed_model_writer.h"

#include <cstdio>
#include <regex>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "identify/cylinder_plant.h"
#include "identify/swing_plant.h"
#include "io/knee_model_loader.h"
#include "io/knee_model_writer.h"
#include "io/yaml_edit.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {

std::string fmtDouble(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// The augmented knee model: the base model's text plus a knee_effects: block.
std::string augmentedKneeYaml(const DiagnosisStudy& study, const SwingModelParams& final, const std::string& header) {
  const std::string text = readFile(study.baseModelPath);
  if (std::regex_search(text, std::regex("(^|\\n)knee_effects:")))
    throw InputError(study.baseModelPath + ": the base model already has a knee_effects: block; --save-model would "
                     "write it twice (diagnose a model without one)");
  const auto& e = final.effects;
  std::string out = "# " + header + "\n" + text + (text.empty() || text.back() == '\n' ? "" : "\n");
  out += "knee_effects:   # swingsim diagnose (docs/diagnosis.md)\n";
  out += "  model_scale: " + fmtDouble(final.kneeModelScale) + "   # refitted scale on the law above\n";
  if (e.coulomb)
    out += "  coulomb_friction: {moment_Nm: " + fmtDouble(e.knee.coulombMoment) +
           ", smoothing_deg_s: " + fmtDouble(e.knee.coulombSmoothingRate * kRadToDeg) + "}\n";
  if (e.viscous) out += "  viscous_damping: {damping_Nm_s_per_rad: " + fmtDouble(e.knee.viscousDamping) + "}\n";
  if (e.assist) out += "  extension_assist_spring: {stiffness_Nm_per_rad: " + fmtDouble(e.knee.assistStiffness) + "}\n";
  return out;
}

// The participant with the participant-level effects and the augmented knee model.
std::string augmentedParticipantYaml(const DiagnosisStudy& study, const SwingBase& base, const SwingModelParams& final,
                                     const std::string& kneeFile, const std::string& header) {
  const std::string& path = study.participantPath;
  std::string text = readFile(path);
  text = std::regex_replace(text, std::regex("(^|\\n)knee_model:[^\\n#]*"), "$1knee_model: " + kneeFile + " ");
  const auto& e = final.effects;
  if (e.toeOff) {
    text = setNestedScalar(text, path, "initial", "hip_flexion_rate_deg_s", fmtDouble(e.toeOffHipRate * kRadToDeg));
    text = setNestedScalar(text, path, "initial", "knee_flexion_rate_deg_s", fmtDouble(e.toeOffKneeRate * kRadToDeg));
  }
  if (e.hipScale) {
    const auto& h = base.participant.hipMoment;
    if (h.kind != HipMomentProfile::Kind::kBiphasicSine)
      throw InputError(path + ": hip_moment_scale can only be written into a biphasic_sine hip moment profile");
    text = setNestedScalar(text, path, "hip_moment", "flexion_amplitude_Nm", fmtDouble(h.flexionAmplitude * e.hipMomentScale));
    text = setNestedScalar(text, path, "hip_moment", "extension_amplitude_Nm",
                           fmtDouble(h.extensionAmplitude * e.hipMomentScale));
  }
  if (e.shankScale) {
    const auto& s = base.participant.shank;
    std::smatch m;
    const std::regex line("(\\n\\s+shank:\\s*\\{)([^}]*)\\}");
    if (!std::regex_search(text, m, line))
      throw InputError(path + ": segments.shank must be a one-line {...} map for --save-model to scale it");
    std::string body = m[2].str();
    body = std::regex_replace(body, std::regex("mass_kg:\\s*[-0-9.eE+]+"), "mass_kg: " + fmtDouble(s.mass * e.shankMassScale));
    body = std::regex_replace(body, std::regex("inertia_kgm2:\\s*[-0-9.eE+]+"),
                              "inertia_kgm2: " + fmtDouble(s.inertia * e.shankMassScale));
    text = m.prefix().str() + m[1].str() + body + "}" + m.suffix().str();
  }
  return "# " + header + "\n" + text;
}

std::string acceptedList(const Diagnosis& dg) {
  std::string accepted;
  for (const auto& a : dg.accepted) accepted += (accepted.empty() ? "" : ", ") + a;
  return accepted.empty() ? "none" : accepted;
}

}  // namespace

std::vector<std::string> saveDiagnosedModel(const DiagnosisStudy& study, const DiagnosisPlant& plant,
                                            const Diagnosis& dg, const std::string& path, const std::string& command) {
  const std::string accepted = acceptedList(dg);
  if (study.plant == PlantKind::kCylinder) {
    MauchModelText text;
    YamlMap m = YamlMap::loadFile(study.baseModelPath);
    text.name = m.getString("name", fileStem(study.baseModelPath)) + "-diagnosed";
    text.flexionDial = m.getDouble("flexion_dial_deg");
    text.extensionDial = m.getDouble("extension_dial_deg");
    text.stop = readHyperextensionStop(m);
    text.description = "Augmented by swingsim diagnose (" + study.name + "): " + (dg.accepted.empty() ? "no effect" : accepted);
    text.header = "Written by " + command + "\nbase model: " + study.baseModelPath + "\naccepted effects: " + accepted +
                  "\ncoefficients refitted on the study's training files";
    writeFileAtomic(path, formatMauchModelYaml(cylinderParams(*dg.final.model), text));
    return {path};
  }
  const SwingModelParams& final = swingParams(*dg.final.model);
  const SwingBase& base = dynamic_cast<const SwingPlant&>(plant).base();
  const std::string header = "Written by " + command + " (accepted: " + accepted + ")";
  std::string partPath = path;
  const auto dot = partPath.rfind(".yaml");
  partPath = (dot == std::string::npos ? partPath : partPath.substr(0, dot)) + "-participant.yaml";
  const std::string kneeText = augmentedKneeYaml(study, final, header);
  const std::string partText = augmentedParticipantYaml(study, base, final, fileStem(path) + ".yaml", header);
  writeFileAtomic(path, kneeText);
  writeFileAtomic(partPath, partText);
  return {path, partPath};
}

}  // namespace swingsim
