#include "io/knee_model_loader.h"
#include "io/swing_record_csv.h"
#include "cli/swing_diagnosis_cli.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <regex>

#include "identify/synthetic_swing.h"
#include "study/diagnosis_study.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "io/participant_loader.h"
#include "io/yaml_edit.h"
#include "io/yaml_reader.h"
#include "report/swing_diagnosis_report.h"
#include "swing/swing_simulation.h"

namespace swingsim::cli {

namespace {

struct Loaded {
  SwingDiagnosisStudy study;
  SwingBase base;
  std::vector<SwingRecord> train, validate;
};

Loaded load(YamlMap& yaml) {
  Loaded l;
  l.study = readSwingDiagnosisStudy(yaml);
  yaml.finish();
  l.base.participant = loadParticipant(l.study.participantPath);
  l.base.knee = loadKneeModel(l.study.baseModelPath);
  for (const auto& p : l.study.train) l.train.push_back(readSwingRecord(p));
  for (const auto& p : l.study.validate) l.validate.push_back(readSwingRecord(p));
  return l;
}

std::string fmtDouble(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// The augmented knee model: the base model's text plus a knee_effects: block.
std::string augmentedKneeYaml(const Loaded& l, const SwingDiagnosis& dg, const std::string& header) {
  const std::string text = readFile(l.study.baseModelPath);
  if (std::regex_search(text, std::regex("(^|\\n)knee_effects:")))
    throw InputError(l.study.baseModelPath + ": the base model already has a knee_effects: block; --save-model would "
                     "write it twice (diagnose a model without one)");
  const auto& e = dg.final.effects;
  std::string out = "# " + header + "\n" + text + (text.empty() || text.back() == '\n' ? "" : "\n");
  out += "knee_effects:   # swingsim diagnose (docs/diagnosis.md)\n";
  out += "  model_scale: " + fmtDouble(dg.final.kneeModelScale) + "   # refitted scale on the law above\n";
  if (e.coulomb)
    out += "  coulomb_friction: {moment_Nm: " + fmtDouble(e.knee.coulombMoment) +
           ", smoothing_deg_s: " + fmtDouble(e.knee.coulombSmoothingRate * kRadToDeg) + "}\n";
  if (e.viscous) out += "  viscous_damping: {damping_Nm_s_per_rad: " + fmtDouble(e.knee.viscousDamping) + "}\n";
  if (e.assist) out += "  extension_assist_spring: {stiffness_Nm_per_rad: " + fmtDouble(e.knee.assistStiffness) + "}\n";
  return out;
}

// The participant with the participant-level effects and the augmented knee model.
std::string augmentedParticipantYaml(const Loaded& l, const SwingDiagnosis& dg, const std::string& kneeFile,
                                     const std::string& header) {
  const std::string& path = l.study.participantPath;
  std::string text = readFile(path);
  text = std::regex_replace(text, std::regex("(^|\\n)knee_model:[^\\n#]*"), "$1knee_model: " + kneeFile + " ");
  const auto& e = dg.final.effects;
  if (e.toeOff) {
    text = setNestedScalar(text, path, "initial", "hip_flexion_rate_deg_s", fmtDouble(e.toeOffHipRate * kRadToDeg));
    text = setNestedScalar(text, path, "initial", "knee_flexion_rate_deg_s", fmtDouble(e.toeOffKneeRate * kRadToDeg));
  }
  if (e.hipScale) {
    const auto& h = l.base.participant.hipMoment;
    if (h.kind != HipMomentProfile::Kind::kBiphasicSine)
      throw InputError(path + ": hip_moment_scale can only be written into a biphasic_sine hip moment profile");
    text = setNestedScalar(text, path, "hip_moment", "flexion_amplitude_Nm", fmtDouble(h.flexionAmplitude * e.hipMomentScale));
    text = setNestedScalar(text, path, "hip_moment", "extension_amplitude_Nm",
                           fmtDouble(h.extensionAmplitude * e.hipMomentScale));
  }
  if (e.shankScale) {
    const auto& s = l.base.participant.shank;
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

}  // namespace

int runSwingCompare(YamlMap& yaml, const Arguments& args) {
  const Loaded l = load(yaml);
  // The base model as diagnose's baseline: knee model scale refitted (no candidate).
  SwingDiagnosisSettings s = l.study.settings;
  s.maxEffects = 1;
  s.candidates = {swingEffectLibrary().front().name};
  const SwingDiagnosis dg = diagnoseSwing(l.base, l.train, l.validate, s);
  const SwingComparison cmp = compareSwing(l.base, dg.baseline, l.train, l.validate);
  std::printf("%s: %s with %s, knee model resistance scale refitted on %zu training file(s) to %.4g\n",
              l.study.name.c_str(), fileStem(l.study.baseModelPath).c_str(), l.base.participant.name.c_str(),
              l.train.size(), dg.baseline.kneeModelScale);
  std::printf("%s", formatSwingComparisonTable(cmp).c_str());
  const auto& wt = dg.baselineWhiteness;
  std::printf("training residual (knee and hip): Ljung-Box Q = %.1f over %d lags (p = %.3g), %d lags outside the 99 %% band: %s\n",
              wt.q, wt.lags, wt.pValue, wt.lagsOutsideBand,
              wt.pValue < s.alpha ? "structure left (not white)" : "consistent with white noise");
  const std::string outDir = args.get("--out", "out/" + l.study.name);
  for (const auto& p : writeSwingResidualPlots(outDir, "compare", cmp)) std::printf("plot: %s\n", p.c_str());
  return 0;
}

int runSwingDiagnose(YamlMap& yaml, const Arguments& args, const std::vector<std::string>& argv) {
  const Loaded l = load(yaml);
  const SwingDiagnosis dg = diagnoseSwing(l.base, l.train, l.validate, l.study.settings);
  const SwingComparison before = compareSwing(l.base, dg.baseline, l.train, l.validate);
  const SwingComparison after = compareSwing(l.base, dg.final, l.train, l.validate);
  const std::string report = formatSwingDiagnosisText(dg, before, after);
  std::printf("%s: %s with %s, %zu training file(s)\n", l.study.name.c_str(), fileStem(l.study.baseModelPath).c_str(),
              l.base.participant.name.c_str(), l.train.size());
  std::printf("where the base model fails (before):\n%s\n%s", formatSwingComparisonTable(before).c_str(), report.c_str());
  // The final model once more with Simbody (the refits used the reference integrator).
  {
    const Participant p = applyParticipantEffects(l.base.participant, dg.final.effects);
    const KneeLawSum law = makeSwingKneeLaw(l.base, dg.final);
    double worst = 0;
    for (const auto& rc : after.records) {
      SwingSetup setup;
      setup.participant = p;
      setup.participant.hipMoment = {};
      setup.participant.hipMoment.kind = HipMomentProfile::Kind::kTable;
      setup.participant.hipMoment.times = rc.data->time;
      setup.participant.hipMoment.moments = rc.data->hipMoment;
      if (dg.final.effects.hipScale)
        for (double& m : setup.participant.hipMoment.moments) m *= dg.final.effects.hipMomentScale;
      setup.participant.initial.hipFlexion = rc.hipPose;
      setup.participant.initial.kneeFlexion = rc.kneePose;
      setup.knee = &law;
      const SwingResult res = simulateSwing(setup, makeSimbodyIntegratorOptions());
      const auto& tr = res.trajectory;
      std::size_t j = 0;
      for (std::size_t i = 0; i < rc.data->time.size(); ++i) {
        const double t = rc.data->time[i];
        while (j + 1 < tr.size() && tr.time[j + 1] < t) ++j;
        if (j + 1 >= tr.size()) break;
        const double a = (t - tr.time[j]) / (tr.time[j + 1] - tr.time[j]);
        const double knee = tr.kneeFlexion[j] + a * (tr.kneeFlexion[j + 1] - tr.kneeFlexion[j]);
        worst = std::max(worst, std::abs(knee - rc.predictedKnee[i]) * kRadToDeg);
      }
    }
    std::printf("Simbody check of the final model (simulateSwing vs the reference integrator used for the refits): "
                "max knee difference %.2g deg\n", worst);
  }
  const std::string outDir = args.get("--out", "out/" + l.study.name);
  std::string md = "# swingsim diagnose: " + l.study.name + "\n\nCommand: `swingsim diagnose";
  for (const auto& a : argv) md += " " + a;
  md += "`\n\n## Before\n\n```\n" + formatSwingComparisonTable(before) + "```\n\n## Ranking and result\n\n```\n" + report +
        "```\n\n## After\n\n```\n" + formatSwingComparisonTable(after) + "```\n\n## Residual plots\n\n";
  std::vector<std::string> plots;
  for (const auto& p : writeSwingResidualPlots(outDir, "before", before)) {
    md += "- before: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
    plots.push_back(p);
  }
  for (const auto& p : writeSwingResidualPlots(outDir, "after", after)) {
    md += "- after: [" + fileStem(p) + "](" + fileStem(p) + ".svg)\n";
    plots.push_back(p);
  }
  writeFileAtomic(outDir + "/report.md", md);
  std::printf("report: %s/report.md\n", outDir.c_str());
  for (const auto& p : plots) std::printf("plot: %s\n", p.c_str());
  if (args.has("--json")) writeFileAtomic(args.get("--json"), formatSwingDiagnosisJson(dg, before, after));
  if (args.has("--save-model")) {
    std::string accepted;
    for (const auto& a : dg.accepted) accepted += (accepted.empty() ? "" : ", ") + a;
    const std::string header = "Written by swingsim diagnose " + args.positional()[0] + " (accepted: " +
                               (accepted.empty() ? "none" : accepted) + ")";
    const std::string kneePath = args.get("--save-model");
    std::string partPath = kneePath;
    const auto dot = partPath.rfind(".yaml");
    partPath = (dot == std::string::npos ? partPath : partPath.substr(0, dot)) + "-participant.yaml";
    const std::string kneeText = augmentedKneeYaml(l, dg, header);
    const std::string partText = augmentedParticipantYaml(l, dg, fileStem(kneePath) + ".yaml", header);
    writeFileAtomic(kneePath, kneeText);
    writeFileAtomic(partPath, partText);
    std::printf("model: %s (knee) and %s (participant: toe-off rates, hip moment, shank; runs with swingsim simulate)\n",
                kneePath.c_str(), partPath.c_str());
  }
  return 0;
}

int generateSwingKinematics(YamlMap& yaml, const Arguments& args) {
  SwingBase base;
  base.participant = loadParticipant(yaml.resolvePath(yaml.getString("participant")));
  base.knee = loadKneeModel(yaml.resolvePath(yaml.getString("model")));
  yaml.getString("name", "");
  yaml.getString("description", "");
  const double noise = yaml.getDouble("noise_deg", mustBeNonNegative);
  const double seedValue = yaml.getDouble("seed", 1.0, [](double v) {
    return v >= 0 && v < 9e15 && v == std::floor(v) ? "" : "must be a whole number >= 0";
  });
  const double interval = yaml.getDouble("sample_interval_s", 0.002, [](double v) {
    return v >= 1e-4 && v <= 0.02 ? "" : "must be in [0.0001, 0.02] s";
  });
  std::string outDir = yaml.resolvePath(yaml.getString("output_dir"));
  if (args.has("--out")) outDir = args.get("--out");
  std::vector<SwingCondition> conditions;
  for (YamlMap& c : yaml.getMapList("conditions")) {
    SwingCondition sc;
    sc.name = c.getString("name");
    sc.timeScale = c.getDouble("time_scale", 1.0, mustBePositive);
    sc.amplitudeScale = c.getDouble("amplitude_scale", 1.0, mustBePositive);
    c.finish();
    conditions.push_back(sc);
  }
  if (conditions.empty()) yaml.fail("conditions", "expected at least one condition", "an empty list");
  SwingModelParams truth;
  std::vector<std::string> hiddenNames;
  if (yaml.has("hidden_effects")) {
    YamlMap h = yaml.getMap("hidden_effects");
    auto& e = truth.effects;
    // One hidden effect: its block, read by `read` (which adds the effect to the truth),
    // then its name kept for the table below.
    auto hidden = [&](const char* name, const std::function<void(YamlMap&, const char*)>& read) {
      if (!h.has(name)) return;
      YamlMap m = h.getMap(name);
      read(m, name);
      m.finish();
      hiddenNames.push_back(name);
    };
    hidden("knee_coulomb_friction", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, m.getDouble("smoothing_deg_s", 57.29577951308232, mustBePositive) * kDegToRad);
      e.knee.coulombMoment = m.getDouble("moment_Nm", mustBeNonNegative);
    });
    hidden("knee_viscous_damping", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, 0);
      e.knee.viscousDamping = m.getDouble("damping_Nm_s_per_rad", mustBeNonNegative);
    });
    hidden("extension_assist_spring", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, 0);
      e.knee.assistStiffness = m.getDouble("stiffness_Nm_per_rad", mustBeNonNegative);
    });
    hidden("toe_off_velocity", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, 0);
      e.toeOffHipRate = m.getDouble("hip_rate_deg_s") * kDegToRad;
      e.toeOffKneeRate = m.getDouble("knee_rate_deg_s") * kDegToRad;
    });
    hidden("hip_moment_scale", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, 0);
      e.hipMomentScale = m.getDouble("scale", mustBePositive);
    });
    hidden("shank_mass_scale", [&](YamlMap& m, const char* name) {
      truth = addSwingEffect(truth, name, 0);
      e.shankMassScale = m.getDouble("scale", mustBePositive);
    });
    h.finish();
  }
  yaml.finish();
  const auto seed = static_cast<std::uint64_t>(seedValue);
  std::vector<std::pair<std::string, std::string>> files;
  std::printf("%-8s %8s %9s %8s %10s %14s%s\n", "file", "tau_x", "amplitude", "samples", "swing_s", "peak_knee_deg",
              hiddenNames.empty() ? "" : "  hidden_knee_rms_deg");
  for (std::size_t i = 0; i < conditions.size(); ++i) {
    const auto& c = conditions[i];
    SwingRecord r = makeSyntheticSwing(base, truth, c, noise, seed + i, interval);
    double peak = -1e9;
    for (double k : r.kneeFlexion) peak = std::max(peak, k * kRadToDeg);
    std::printf("%-8s %8.3f %9.3f %8zu %10.3f %14.1f", c.name.c_str(), c.timeScale, c.amplitudeScale, r.time.size(),
                r.time.back(), peak);
    if (!hiddenNames.empty()) {
      // The hidden effects alone along this condition: noiseless truth minus the plain model.
      SwingModelParams plain;
      const SwingRecord clean = makeSyntheticSwing(base, truth, c, 0.0, 0, interval);
      const SwingRecord none = makeSyntheticSwing(base, plain, c, 0.0, 0, interval);
      double s = 0;
      const std::size_t n = std::min(clean.time.size(), none.time.size());
      for (std::size_t k = 0; k < n; ++k) s += std::pow((clean.kneeFlexion[k] - none.kneeFlexion[k]) * kRadToDeg, 2);
      std::printf("  %19.2f", std::sqrt(s / static_cast<double>(n)));
    }
    std::printf("\n");
    files.emplace_back(outDir + "/" + c.name + ".csv", formatSwingRecordCsv(r));
  }
  for (const auto& [path, text] : files) writeFileAtomic(path, text);
  std::printf("wrote %zu swing kinematics files to %s (participant %s, knee %s, noise %s deg, seed %llu)\n", files.size(),
              outDir.c_str(), base.participant.name.c_str(), base.knee.name.c_str(), formatNumber(noise).c_str(),
              static_cast<unsigned long long>(seed));
  return 0;
}

}  // namespace swingsim::cli
