#pragma once
// The unpublished assumptions of the knee-axis sweep ("How sure is the optimum"), in one
// table: each with its unit, the nominal value the participant and knee
// files say, a plausible range and where that range comes from (docs/uncertainty.md lists
// the same table). Each entry applies a value to a copy of one participant's inputs; the
// uncertainty runner (sweep_uncertainty.h) sweeps those copies.
#include <functional>
#include <string>
#include <vector>

#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Everything one participant's sweep depends on that an assumption may change: a copy of
/// the participant, of its knee model's spec (the knee law is rebuilt from it per swing
/// set: makeSweepVariantKnee) and of the integrator settings, plus the hip-effort
/// adaptation exponent, which acts per lowering (calcAdaptedParticipant).
struct SweepVariant {
  Participant participant;
  KneeModel knee;  ///< path, name and kind as loaded; `spec` is what assumptions change
  SwingOptions swing;
  /// a in [0, 1]: the hip moment at lowering d is multiplied by (I_k(d) / I_k(0))^a, I_k
  /// the shank + foot inertia about the knee (Hale 1990: amputees raise hip effort when
  /// the shank changes). 0 = the hip moment replayed unchanged at every lowering (the files).
  double hipEffortExponent = 0;
};

/// The range of one assumption for one participant. `applicable` false: the assumption
/// does not exist for this participant (the hip-moment shape of a tabulated profile);
/// then low = high = nominal and it is not varied.
struct AssumptionRange {
  double nominal = 0, low = 0, high = 0;
  bool applicable = true;
};

/// One unpublished assumption.
struct SweepAssumption {
  std::string key;   ///< JSON/report key: com_rule, hip_time_scale, ...
  std::string name;  ///< what it is, for tables and figures
  std::string unit;  ///< unit of the values ("deg", "N m", "s/rad"; "1" dimensionless, "choice" discrete)
  /// A two-way choice: value 0 = the first reading, 1 = the second (`choices`); a Monte
  /// Carlo draw takes each with probability 1/2.
  bool discrete = false;
  std::vector<std::string> choices;  ///< discrete: the names of values 0 and 1
  /// Drawn uniformly in log(value) instead of value (a scale parameter: the accuracy).
  bool logUniform = false;
  std::string source;  ///< why this range: a published source or the stated reasoning
  /// The range for a participant (its nominal read from the variant as loaded).
  std::function<AssumptionRange(const SweepVariant&)> calcRange;
  /// The value the variant currently has (for discrete ones 0 or 1).
  std::function<double(const SweepVariant&)> read;
  /// Sets the value on the variant (its knee spec, participant or integrator settings).
  std::function<void(SweepVariant&, double)> apply;
};

/// The table, in a fixed order (the order of the Monte Carlo draws).
const std::vector<SweepAssumption>& sweepAssumptions();

/// The value at fraction u in [0, 1] of a range: low + u (high - low), or the same in
/// log(value) for a logUniform entry, or (discrete) low if u < 0.5 else high.
double calcAssumptionValue(const SweepAssumption& assumption, const AssumptionRange& range, double u);

/// The ranges of every assumption of sweepAssumptions() for `variant` (its values as loaded),
/// in the table's order.
std::vector<AssumptionRange> calcAssumptionRanges(const SweepVariant& variant);

/// Sets every assumption of sweepAssumptions() on `variant` to its value at fraction `u[k]` of
/// `ranges[k]` (calcAssumptionValue): one Monte Carlo draw.
void applyAssumptionDraw(SweepVariant& variant, const std::vector<AssumptionRange>& ranges,
                         const std::vector<double>& u);

/// A variant's knee law: the knee model's law rebuilt from `variant.knee.spec`
/// (makeKneeModelLaw) plus the participant's friction (makeKneeLaw).
KneeLawSum makeSweepVariantKnee(const SweepVariant& variant);

/// Shank + foot moment of inertia about the knee axis at a lowering, kg m^2 (the shank's
/// and foot's own inertias plus m r^2 of each COM; the foot perpendicular to the shank).
double calcBelowKneeInertia(const Participant& participant, double lowering);

/// The participant whose hip moment is scaled for the hip-effort adaptation at `lowering`:
/// amplitudes (or tabulated moments) times (I_k(lowering) / I_k(0))^exponent.
Participant calcAdaptedParticipant(const Participant& participant, double lowering, double exponent);

}  // namespace swingsim
