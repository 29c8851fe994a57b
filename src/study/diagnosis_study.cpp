#include "study/diagnosis_study.h"

#include "core/output_files.h"
#include "identify/cylinder_plant.h"
#include "identify/swing_plant.h"
#include "io/bench_csv.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "io/swing_record_csv.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {

// The keys both kinds share: name, description, train, validate, candidates, acceptance.
void readCommon(YamlMap& yaml, const std::vector<std::string>& known, const char* kindName, std::string& name,
                std::vector<std::string>& train, std::vector<std::string>& validate, EffectSelectionSettings& st) {
  name = yaml.getString("name", fileStem(yaml.path()));
  yaml.getString("description", "");
  for (const auto& p : yaml.getStringList("train")) train.push_back(yaml.resolvePath(p));
  for (const auto& p : yaml.getStringList("validate")) validate.push_back(yaml.resolvePath(p));
  if (train.empty()) yaml.fail("train", "expected at least one CSV", "an empty list");
  if (validate.empty())
    yaml.fail("validate", "expected at least one CSV (the acceptance rule needs held-out data)", "an empty list");
  std::vector<std::string> stems;
  for (const auto& list : {train, validate})
    for (const auto& p : list) {
      for (const auto& st2 : stems)
        if (st2 == fileStem(p)) yaml.fail("validate", "two files share the stem '" + st2 + "' (results are keyed by stem)", p);
      stems.push_back(fileStem(p));
    }
  if (yaml.has("candidates")) {
    for (const auto& c : yaml.getStringList("candidates")) {
      bool ok = false;
      for (const auto& k : known) ok = ok || k == c;
      if (!ok) {
        std::string all;
        for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
        yaml.fail("candidates", std::string("unknown ") + kindName + " effect (known: " + all + ")", c);
      }
      st.candidates.push_back(c);
    }
    if (st.candidates.empty()) yaml.fail("candidates", "expected at least one effect", "an empty list");
  }
  if (yaml.has("acceptance")) {
    YamlMap a = yaml.getMap("acceptance");
    st.alpha = a.getDouble("alpha", st.alpha, [](double v) { return v > 0 && v < 0.5 ? "" : "must be in (0, 0.5)"; });
    st.minValidationImprovement = a.getDouble("min_validation_improvement", st.minValidationImprovement,
                                              [](double v) { return v >= 0 && v < 1 ? "" : "must be in [0, 1)"; });
    st.maxEffects = a.getInt("max_effects", st.maxEffects);
    if (st.maxEffects < 1 || st.maxEffects > 6) a.fail("max_effects", "must be 1 to 6", std::to_string(st.maxEffects));
    st.measurementNoise = a.getDouble("measurement_noise", st.measurementNoise, mustBeNonNegative);
    st.explainedNoiseRatio = a.getDouble("explained_noise_ratio", st.explainedNoiseRatio, [](double v) {
      return v >= 1 && v <= 10 ? "" : "must be in [1, 10]";
    });
    st.whitenessLags = a.getInt("whiteness_lags", st.whitenessLags);
    if (st.whitenessLags < 1 || st.whitenessLags > 1000)
      a.fail("whiteness_lags", "must be 1 to 1000", std::to_string(st.whitenessLags));
    a.finish();
  }
}

}  // namespace

DiagnosisStudy readDiagnosisStudy(YamlMap& yaml) {
  DiagnosisStudy s;
  s.path = yaml.path();
  if (!yaml.has("kind")) yaml.getString("kind");  // "required key is missing"
  s.plant = yaml.getChoice("kind", {"cylinder-diagnosis", "swing-diagnosis"}, "") == "swing-diagnosis" ? PlantKind::kSwing
                                                                                                      : PlantKind::kCylinder;
  if (s.plant == PlantKind::kSwing) s.participantPath = yaml.resolvePath(yaml.getString("participant"));
  s.baseModelPath = yaml.resolvePath(yaml.getString("base_model"));
  readCommon(yaml, effectNames(s.plant), plantName(s.plant).c_str(), s.name, s.train, s.validate, s.settings);
  if (s.plant == PlantKind::kCylinder) {
    s.fitSwitches = yaml.getBool("fit_switches", false);
    s.plotSeconds = yaml.getDouble("plot_seconds", s.plotSeconds, mustBePositive);
  }
  return s;
}

DiagnosisStudy loadDiagnosisStudy(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  DiagnosisStudy s = readDiagnosisStudy(yaml);
  yaml.finish();
  return s;
}

std::unique_ptr<DiagnosisPlant> loadDiagnosisPlant(const DiagnosisStudy& study, std::size_t extraTrainRows) {
  if (study.plant == PlantKind::kCylinder) {
    const MauchCylinderParams base = loadMauchCylinder(study.baseModelPath);
    const auto minRows = static_cast<std::size_t>(MauchCylinder(base).numCoefficients()) + extraTrainRows;
    std::vector<BenchData> train, validate;
    for (const auto& p : study.train) train.push_back(readBenchCsv(p, minRows));
    for (const auto& p : study.validate) validate.push_back(readBenchCsv(p, 3));
    return std::make_unique<CylinderPlant>(base, std::move(train), std::move(validate), study.fitSwitches,
                                           study.plotSeconds);
  }
  SwingBase base;
  base.participant = loadParticipant(study.participantPath);
  base.knee = loadKneeModel(study.baseModelPath);
  std::vector<SwingRecord> train, validate;
  for (const auto& p : study.train) train.push_back(readSwingRecord(p));
  for (const auto& p : study.validate) validate.push_back(readSwingRecord(p));
  return std::make_unique<SwingPlant>(std::move(base), std::move(train), std::move(validate), study.integratorTolerance);
}

}  // namespace swingsim
