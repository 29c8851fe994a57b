#include "study/diagnosed_model_writer.h"

#include <filesystem>
#include <stdexcept>

#include "core/input_error.h"
#include "core/output_files.h"
#include "identify/cylinder_plant.h"
#include "identify/swing_plant.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {

namespace {

std::string acceptedList(const Diagnosis& dg) {
  std::string accepted;
  for (const auto& a : dg.accepted) accepted += (accepted.empty() ? "" : ", ") + a;
  return accepted.empty() ? "none" : accepted;
}

// The base cylinder model with the diagnosed parameters: its one dial setting carries the
// refitted coefficients, its effects the accepted ones.
KneeModelSpec diagnosedCylinder(const DiagnosisStudy& study, const MauchCylinderParams& final,
                                const std::string& accepted) {
  KneeModelSpec spec = loadKneeModel(study.baseModelPath).spec;
  spec.name = (spec.name.empty() ? fileStem(study.baseModelPath) : spec.name) + "-diagnosed";
  spec.description = "Augmented by swingsim diagnose (" + study.name + "): " + accepted;
  MauchKnee* mauch = spec.as<MauchKnee>();
  if (!mauch)  // the study's reader loads its base model as a cylinder (loadMauchCylinder)
    throw std::logic_error(study.baseModelPath + ": a cylinder diagnosis's base model is not kind: mauch");
  mauch->cylinder = final;
  mauch->hasCylinderEffects = final.effects.any();
  MauchDialSetting setting;
  setting.flexionDial = mauch->flexionDial;
  setting.extensionDial = mauch->extensionDial;
  for (int i = 0; i < final.phases; ++i)
    setting.rows.push_back({i + 1, final.coefficients[static_cast<std::size_t>(i)]});
  mauch->settings = {setting};
  return spec;
}

// The base knee model with the diagnosed knee effects and the refitted scale on its law.
KneeModelSpec diagnosedKnee(const DiagnosisStudy& study, const KneeModelSpec& base, const SwingModelParams& final,
                            const std::string& accepted) {
  KneeModelSpec spec = base;
  if (spec.hasKneeEffects)
    throw InputError(study.baseModelPath +
                     ": knee_effects: the base model already has added knee effects; --save-model "
                     "would stack the diagnosed ones on them (diagnose a model without knee_effects)");
  spec.name = (spec.name.empty() ? fileStem(study.baseModelPath) : spec.name) + "-diagnosed";
  spec.description = "Augmented by swingsim diagnose (" + study.name + "): " + accepted;
  spec.hasKneeEffects = true;
  spec.kneeEffects = final.effects.knee;
  spec.kneeEffects.modelScale = final.kneeModelScale;
  return spec;
}

}  // namespace

std::vector<std::string> saveDiagnosedModel(const DiagnosisStudy& study, const DiagnosisPlant& plant,
                                            const Diagnosis& dg, const std::string& path, const std::string& command) {
  const std::string accepted = acceptedList(dg);
  const std::string header = "Written by " + command + "\nbase model: " + study.baseModelPath +
                             "\naccepted effects: " + accepted +
                             "\nfree parameters refitted on the study's training files";
  if (study.plant == PlantKind::kSweep)
    throw InputError(
        "diagnose: --save-model: a sweep diagnosis changes no single model file (its shared values act "
        "on every participant of the sweep study); the fitted values are in the report and --json");
  if (study.plant == PlantKind::kCylinder) {
    writeFileAtomic(path,
                    formatKneeModelYaml(diagnosedCylinder(study, cylinderParams(*dg.final.model), accepted), header));
    return {path};
  }
  const SwingModelParams& final = swingParams(*dg.final.model);
  const SwingBase& base = dynamic_cast<const SwingPlant&>(plant).base();
  const std::string kneeText = formatKneeModelYaml(diagnosedKnee(study, base.knee.spec, final, accepted), header);
  // The participant with the participant-level effects (toe-off rates, hip moment, shank),
  // running on the diagnosed knee model.
  std::string partPath = path;
  const auto dot = partPath.rfind(".yaml");
  partPath = (dot == std::string::npos ? partPath : partPath.substr(0, dot)) + "-participant.yaml";
  Participant participant = applyParticipantEffects(base.participant, final.effects);
  participant.kneeModelPath = std::filesystem::absolute(path).string();
  const std::string dir = std::filesystem::path(partPath).parent_path().string();
  const std::string partText = formatParticipantYaml(participant, dir.empty() ? "." : dir, header);
  writeFileAtomic(path, kneeText);
  writeFileAtomic(partPath, partText);
  return {path, partPath};
}

}  // namespace swingsim
