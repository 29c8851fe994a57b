#pragma once
// A knee model: the plain data of a knee model file (models/*.yaml) and the knee law it
// makes (the model's resisting law, its added knee effects, then its hyperextension stop).
#include <string>
#include <vector>

#include "core/units.h"
#include "knee/damping_table.h"
#include "knee/impedance_state_machine.h"
#include "knee/joint_stop.h"
#include "knee/knee_added_effects.h"
#include "knee/knee_law.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {

enum class KneeModelKind { kDampingTable, kMauch, kImpedanceStateMachine };

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

/// Everything a knee model file says.
struct KneeModelSpec {
  KneeModelKind kind = KneeModelKind::kDampingTable;
  std::string name;         ///< empty: the file stem is used
  std::string description, source;
  /// kind damping_table. An unset smoothing speed is 30 deg/s (the file format's default).
  DampingTableParams table = [] {
    DampingTableParams t;
    t.smoothingRate = 30.0 * kDegToRad;
    return t;
  }();
  /// kind mauch: the cylinder at the chosen dial setting (its coefficients from `settings`).
  MauchCylinderParams cylinder;
  double flexionDial = 90, extensionDial = 90;  ///< deg: the dial setting in use
  std::vector<MauchDialSetting> settings;       ///< every tabulated setting
  /// kind impedance_state_machine: the microprocessor knee's swing controller.
  ImpedanceStateMachineParams stateMachine;
  bool hasGeometry = true;                      ///< geometry written in the file
  bool hasCylinderEffects = false;              ///< an `effects:` map (added cylinder effects)
  bool hasKneeEffects = false;                  ///< a `knee_effects:` map
  KneeAddedEffectsParams kneeEffects;
  bool hasStop = false;                         ///< a `hyperextension_stop:` map (else defaults)
  JointStopParams stop;
};

/// The law a spec makes: the resisting law (scaled by kneeEffects.modelScale), the added
/// knee effects, then the stop. Throws std::invalid_argument from the laws' checks.
KneeLawSum makeKneeModelLaw(const KneeModelSpec& spec);

/// A loaded knee model.
struct KneeModel {
  std::string path;
  std::string name;   ///< `name:` key, or the file stem
  std::string kind;   ///< `kind:` key: damping_table, mauch, impedance_state_machine
  KneeLawSum law;     ///< the model's resisting law(s) followed by the hyperextension stop
  KneeModelSpec spec;  ///< what the file said
};

}  // namespace swingsim
