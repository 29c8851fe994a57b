#include "io/knee_model_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/input_error.h"

namespace swingsim {
namespace {

using ::testing::HasSubstr;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string writeTemp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "swingsim_knee_model_loader_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& path) {
  try {
    loadKneeModel(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kValidHead = R"(kind: mauch
phases: 4
switches:
  velocity_width_m_per_s: 0.0005
  position_width_m: 0.0005
  hyperextension_position_m: 0.00005
  latch_rate_per_s: 10000
flexion_dial_deg: 90
extension_dial_deg: 90
settings:
  - flexion_dial_deg: 90
    extension_dial_deg: 90
    coefficients:
)";

TEST(KneeModelLoader, MauchFourPhaseModelWorksInRadiansWithItsLatchState) {
  const KneeModel model = loadKneeModel(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-4phase.yaml");
  EXPECT_STREQ(model.spec.kindKey(), "mauch");
  ASSERT_EQ(model.law.size(), 2u);  // cylinder, then the hyperextension stop
  EXPECT_EQ(model.law.part(1).name(), "hyperextension stop");
  ASSERT_EQ(model.law.numStates(), 1);
  double z = 0;
  model.law.initialStates(&z);
  EXPECT_EQ(z, 1.0);
  // Swing flexion at 30 deg and 5 rad/s: phase 2 resists flexion.
  const double m = model.law.calcMoment({30 * kDeg, 5.0}, &z);
  EXPECT_LT(m, 0.0);
  // Order of magnitude: c2 * (arm * rate) * arm with arm ~ 0.02 m/rad: ~ 2 N m.
  EXPECT_GT(m, -20.0);
  double zdot = 1;
  model.law.calcStateDerivatives({30 * kDeg, 5.0}, &z, &zdot);
  EXPECT_NEAR(zdot, 0.0, 1e-6);  // flexing: latch frozen
}

TEST(KneeModelLoader, MauchTwoPhaseModelLoads) {
  const auto p = loadMauchCylinder(std::string(SWINGSIM_SOURCE_DIR) + "/models/mauch-2phase.yaml");
  EXPECT_EQ(p.phases, 2);
  ASSERT_EQ(p.coefficients.size(), 2u);
  EXPECT_GT(p.coefficients[0].c, p.coefficients[1].c);  // phase 1 is the high-force phase
}

TEST(KneeModelLoader, MissingPhaseNamesFileLineAndPhase) {
  const std::string path = writeTemp("missing.yaml", std::string(kValidHead) +
                                                         "      - {phase: 1, f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n"
                                                         "      - {phase: 2, f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n"
                                                         "      - {phase: 4, f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n");
  EXPECT_THAT(errorOf(path), HasSubstr("missing.yaml:13: settings[0].coefficients: phase 3 is missing"));
}

TEST(KneeModelLoader, RejectsBadPhaseCountsDialsAndDuplicates) {
  std::string text = kValidHead;
  text.replace(text.find("phases: 4"), 9, "phases: 3");
  EXPECT_THAT(errorOf(writeTemp("p3.yaml", text)), HasSubstr("p3.yaml:2: phases: must be 2 or 4"));

  text = kValidHead;
  text.replace(text.find("flexion_dial_deg: 90"), 20, "flexion_dial_deg: 45");
  EXPECT_THAT(errorOf(writeTemp("dial.yaml", text)),
              HasSubstr("dial.yaml:8: flexion_dial_deg: must be a dial setting"));

  text = std::string(kValidHead) +
         "      - {phase: 1, f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n"
         "      - {phase: 1, f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n";
  EXPECT_THAT(errorOf(writeTemp("dup.yaml", text)), HasSubstr("phase appears twice"));

  text = kValidHead;
  text.replace(text.find("extension_dial_deg: 90\nsettings"), 22, "extension_dial_deg: 180");
  for (int phase = 1; phase <= 4; ++phase)
    text += "      - {phase: " + std::to_string(phase) + ", f_N: 1, k_N_per_m: 2, c_Ns_per_m: 3}\n";
  EXPECT_THAT(errorOf(writeTemp("nodial.yaml", text)),
              HasSubstr("no coefficient set in settings for this dial setting (got F90E180)"));

  text = kValidHead;
  text.replace(text.find("  position_width_m: 0.0005\n"), 26, "");
  EXPECT_THAT(errorOf(writeTemp("nowidth.yaml", text)),
              HasSubstr("switches.position_width_m: required key is missing"));
}

// Round trip (MuJoCo's xml write/read tests): every knee model file of the repository, and
// variants with added cylinder effects, added knee effects and another stop, load -> write
// -> load to the same model (same text when written again, same knee moments everywhere).
TEST(KneeModelFormat, LoadWriteLoadGivesTheSameModel) {
  const std::string root = SWINGSIM_SOURCE_DIR;
  std::vector<KneeModelSpec> specs;
  for (const char* f : {"/models/damping-table-default.yaml", "/models/mauch-2phase.yaml", "/models/mauch-4phase.yaml",
                        "/models/pneumatic-knee.yaml"})
    specs.push_back(loadKneeModel(root + f).spec);
  KneeModelSpec cylinder = specs[1];
  MauchKnee& mauch = std::get<MauchKnee>(cylinder.kind);
  mauch.hasCylinderEffects = true;
  mauch.cylinder.effects.hyperextensionPhase = true;
  mauch.cylinder.effects.hyperextension = {-400, 5e5, 1.2e4};
  mauch.cylinder.effects.coulombFriction = true;
  mauch.cylinder.effects.coulombForce = 12.5;
  mauch.cylinder.effects.coulombWidth = 0.02;
  specs.push_back(cylinder);
  KneeModelSpec knee = specs[0];
  knee.hasKneeEffects = true;
  knee.kneeEffects.modelScale = 1.25;
  knee.kneeEffects.coulombMoment = 0.7;
  knee.kneeEffects.coulombSmoothingRate = 2.0;
  knee.kneeEffects.viscousDamping = 0.3;
  // A user's expression in the hip's state and the time too, as a diagnosis saves it.
  knee.kneeEffects.expressions.push_back({"my_cushion",
                                          "-c * knee_rate_rad_s * (knee_deg < 20 ? 1 : 0) + k * hip_rad * time_s",
                                          {{"c", "N m s/rad", 1.25}, {"k", "N m/(rad s)", -0.5}}});
  knee.hasStop = true;
  knee.stop.lower = -2.5 * kDegToRad;
  knee.stop.stiffness = 1500;
  specs.push_back(knee);
  for (const KneeModelSpec& spec : specs) {
    const std::string text = formatKneeModelYaml(spec);
    const KneeModel back = parseKneeModel(text, "models/roundtrip.yaml");
    EXPECT_EQ(formatKneeModelYaml(back.spec), text) << spec.name;
    const KneeLawSum original = makeKneeModelLaw(spec);
    ASSERT_EQ(back.law.size(), original.size()) << spec.name;
    for (double flexion : {-0.05, 0.0, 0.3, 1.0})
      for (double rate : {-5.0, 0.0, 2.0}) {
        std::vector<double> z(static_cast<std::size_t>(std::max(1, original.numStates())), 1.0);
        const KneeKinematics k{flexion, rate, 0.4, 1.0, 0.2};
        EXPECT_EQ(back.law.calcMoment(k, z.data()), original.calcMoment(k, z.data()))
            << spec.name << " " << flexion << " " << rate;
      }
  }
}

TEST(KneeModelLoader, APneumaticChamberThePistonWouldReachIsRefusedAtItsLine) {
  const std::string path = writeTemp("short-chamber.yaml", R"(kind: pneumatic
pneumatic:
  bore_m: 0.035
  lever_arm_m: 0.035
  chamber_length_m: 0.08
  flexion_valve_time_s: 0.05
  extension_valve_time_s: 0.02
)");
  const std::string e = errorOf(path);
  EXPECT_THAT(e, HasSubstr("short-chamber.yaml:5: pneumatic.chamber_length_m"));
  EXPECT_THAT(e, HasSubstr("lever_arm_m x 2.618"));
}

// A user's expression that does not parse is refused at its line with the parser's message
// and where in the expression it stopped.
TEST(KneeModelLoader, ABadUserExpressionNamesItsLineAndPosition) {
  const std::string path = writeTemp("bad-expression.yaml", R"(kind: damping_table
damping_table: {flexion_deg: [0, 70], moment_Nm: [2, 2]}
knee_effects:
  expressions:
    - name: my_cushion
      knee_moment_Nm: "-c * knee_rte_rad_s"
      parameters: {c: {unit: N m s/rad, value: 1}}
)");
  const std::string e = errorOf(path);
  EXPECT_THAT(e, HasSubstr("bad-expression.yaml:6: knee_effects.expressions[0].knee_moment_Nm:"));
  EXPECT_THAT(e, HasSubstr("knee_rte_rad_s"));
  EXPECT_THAT(e, HasSubstr("character 6"));
  const std::string unused = writeTemp("unused-parameter.yaml", R"(kind: damping_table
damping_table: {flexion_deg: [0, 70], moment_Nm: [2, 2]}
knee_effects:
  expressions:
    - {name: x, knee_moment_Nm: "-2 * knee_rate_rad_s", parameters: {c: {value: 1}}}
)");
  EXPECT_THAT(errorOf(unused), HasSubstr("parameter 'c' is not used"));
}

}  // namespace
}  // namespace swingsim
