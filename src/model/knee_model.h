#pragma once
// A knee model: the plain data of a knee model file (models/*.yaml) and the knee law it
// makes (the model's resisting law, its added knee effects, then its hyperextension stop).
#include <string>
#include <variant>
#include <vector>

#include "core/units.h"
#include "knee/damping_table.h"
#include "knee/impedance_state_machine.h"
#include "knee/joint_stop.h"
#include "knee/knee_added_effects.h"
#include "knee/knee_law.h"
#include "knee/mauch_cylinder.h"
#include "knee/pneumatic_cylinder.h"

namespace swingsim {

/// One row of a Mauch dial setting's coefficient table (Chien 2014 Table 1).
struct MauchCoefficientRow {
  int phase = 0;  ///< 1-based
  MauchPhaseCoefficients coefficients;
};

/// The coefficients of every phase at one valve dial setting.
struct MauchDialSetting {
  double flexionDial = 90, extensionDial = 90;  ///< deg: 0, 90 or 180
  std::vector<MauchCoefficientRow> rows;
};

/// kind damping_table: a dynamometer damping table. An unset smoothing speed is 30 deg/s
/// (the file format's default).
struct DampingTableKnee {
  static constexpr const char* kKey = "damping_table";
  DampingTableParams table = [] {
    DampingTableParams t;
    t.smoothingRate = 30.0 * kDegToRad;
    return t;
  }();
};

/// kind mauch: the cylinder at the chosen dial setting (its coefficients from `settings`).
struct MauchKnee {
  static constexpr const char* kKey = "mauch";
  MauchCylinderParams cylinder;
  double flexionDial = 90, extensionDial = 90;  ///< deg: the dial setting in use
  std::vector<MauchDialSetting> settings;       ///< every tabulated setting
  bool hasGeometry = true;                      ///< geometry written in the file
  bool hasCylinderEffects = false;              ///< an `effects:` map (added cylinder effects)
};

/// kind impedance_state_machine: the microprocessor knee's swing controller.
struct ImpedanceStateMachineKnee {
  static constexpr const char* kKey = "impedance_state_machine";
  ImpedanceStateMachineParams stateMachine;
};

/// kind pneumatic: an air cylinder with flexion and extension valves.
struct PneumaticKnee {
  static constexpr const char* kKey = "pneumatic";
  PneumaticCylinderParams cylinder;
};

/// The knee kinds, one alternative each: its `kind:` key and parameters here, the law it
/// makes in knee_model.cpp, its keys in io/knee_model_loader.cpp. Both are std::visit over
/// this variant, so a kind added here and forgotten there does not compile.
using KneeKind = std::variant<DampingTableKnee, MauchKnee, ImpedanceStateMachineKnee, PneumaticKnee>;

/// Everything a knee model file says.
struct KneeModelSpec {
  KneeKind kind;     ///< the kind and its parameters (a damping table unless set)
  std::string name;  ///< empty: the file stem is used
  std::string description, source;
  bool hasKneeEffects = false;  ///< a `knee_effects:` map
  KneeAddedEffectsParams kneeEffects;
  bool hasStop = false;  ///< a `hyperextension_stop:` map (else defaults)
  JointStopParams stop;

  /// The `kind:` key: damping_table, mauch, impedance_state_machine, pneumatic.
  const char* kindKey() const;
  /// The parameters of kind K, or nullptr if the spec is another kind.
  template <class K>
  K* as() {
    return std::get_if<K>(&kind);
  }
  template <class K>
  const K* as() const {
    return std::get_if<K>(&kind);
  }
};

/// The law a spec makes: the resisting law (scaled by kneeEffects.modelScale), the added
/// knee effects, then the stop. Throws std::invalid_argument from the laws' checks.
KneeLawSum makeKneeModelLaw(const KneeModelSpec& spec);

/// A loaded knee model.
struct KneeModel {
  std::string path;
  std::string name;    ///< `name:` key, or the file stem
  KneeLawSum law;      ///< the model's resisting law(s) followed by the hyperextension stop
  KneeModelSpec spec;  ///< what the file said
};

}  // namespace swingsim
