#pragma once
// Loads a knee model YAML (models/*.yaml) into a knee law: the model's own law (damping
// table or Mauch cylinder) plus its hyperextension stop. Knee friction belongs to the
// participant's knee unit (Burkett Table 2, Tc) and is added by the participant loader.
#include <string>

#include "knee/joint_stop.h"
#include "knee/knee_added_effects.h"
#include "knee/knee_law.h"
#include "model/knee_model.h"
#include "knee/mauch_cylinder.h"

namespace swingsim {


/// Reads a knee model. Throws InputError (`file:line: key: ...`) on any bad input.
KneeModel loadKneeModel(const std::string& path);
/// Same, from YAML text (tests, fuzzers); `path` is used in messages and as the name's default.
KneeModel parseKneeModel(const std::string& text, const std::string& path);

/// Reads the Mauch cylinder of a `kind: mauch` model (phases, geometry, switches and the
/// coefficient set of the selected dial setting; docs/mauch.md). Throws InputError.
MauchCylinderParams loadMauchCylinder(const std::string& path);

class YamlMap;
/// Reads the Mauch part of a `kind: mauch` model already opened as `yaml`.
MauchCylinderParams readMauchCylinder(YamlMap& yaml);

/// Reads an `effects:` map of an augmented Mauch model (docs/diagnosis.md): optional blocks
/// hyperextension_phase {f_N, k_N_per_m, c_Ns_per_m} (2-phase models only; `phases` 0 skips
/// that check), coulomb_friction {force_N, width_m_per_s}, orifice_quadratic
/// {coefficient_Ns2_per_m2}, inertia {mass_kg}, position_dependent_damping
/// {coefficient_Ns_per_m2}. Calls finish() on `effects`. Throws InputError.
MauchAddedEffects readMauchAddedEffects(YamlMap& effects, int phases);

/// Reads a `knee_effects:` map (docs/diagnosis.md, the swing diagnosis's augmented model):
/// optional model_scale (> 0, multiplies the model's own law), coulomb_friction {moment_Nm, smoothing_deg_s (57.3)}, viscous_damping
/// {damping_Nm_s_per_rad}, extension_assist_spring {stiffness_Nm_per_rad}; all >= 0. Any
/// knee model kind may carry it; the law is added before the hyperextension stop. Calls
/// finish() on the map. Throws InputError.
KneeAddedEffectsParams readKneeAddedEffects(YamlMap& effects);

/// Reads a `hyperextension_stop:` block (all keys optional, defaults in JointStopParams
/// with the stop engaging at full extension).
JointStopParams readHyperextensionStop(YamlMap& yaml);

}  // namespace swingsim
