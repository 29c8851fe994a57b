#pragma once
// The swing at a tuning's knob values (`swingsim tune`, Python swingsim.tune, swingsim serve's
// tuning): the knee model with its knob keys set through KneeModelKnobs (so each value gets
// the knee file's own checks, for every knee kind), the knee-axis lowering and the added mass.
#include <string>
#include <utility>
#include <vector>

#include "io/knee_model_knobs.h"
#include "model/leg_parameters.h"
#include "sweep/knee_tuning.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// Whether a knob is the leg's (kLoweringKnob, kAddedMassKnob, kAddedMassDistanceKnob), not a
/// key of the knee file.
bool isLegTuningKnob(const std::string& key);

/// The leg at `value` of leg knob `key`, the lowering and added mass otherwise `lowering` and
/// `added`: throws InputError where the leg geometry refuses it (a negative mass or lowering,
/// a shank too short, a mass below the shank's end).
void checkLegAtKnob(const Participant& p, double lowering, AddedMass added, const std::string& key, double value);

/// The knee model, lowering and added mass at knob values.
struct TunedSetting {
  KneeModel knee;
  double lowering = 0;  ///< m
  AddedMass added;
};

class TuningModel {
 public:
  /// `knobs` in the order of the values later given; knob keys other than kLoweringKnob,
  /// kAddedMassKnob and kAddedMassDistanceKnob are keys of the knee file `knee`.
  /// `fixedKneeSettings` are set at every point, before the knobs (a setting also a knob is
  /// the knob's). `lowering` and `added` hold where they are not knobs. Throws InputError.
  TuningModel(Participant participant, KneeModelKnobs knee, std::vector<TuningKnob> knobs, double lowering,
              AddedMass added, std::vector<std::pair<std::string, double>> fixedKneeSettings = {});

  /// The knee model (the fixed settings, then the knee knobs' values), lowering and added
  /// mass at `values` (one a knob). Throws InputError where the knee loader refuses a value.
  TunedSetting at(const std::vector<double>& values) const;
  /// Each knob at both ends of its range, the others at their lower ends, through the knee
  /// loader or the leg geometry (checkLegAtKnob): throws InputError naming the knob and the
  /// end, so no point of the ranges is refused later.
  void checkKnobRanges() const;
  /// One swing at `values`; safe from several threads. Throws RunError, InputError.
  SwingResult simulate(const std::vector<double>& values, const SwingOptions& options) const;
  const Participant& participant() const { return participant_; }

 private:
  Participant participant_;
  KneeModelKnobs kneeFile_;
  std::vector<TuningKnob> knobs_;
  double lowering_ = 0;
  AddedMass added_;
  /// The fixed settings that are not knobs: keys and values, set before the knobs' at every point.
  std::pair<std::vector<std::string>, std::vector<double>> fixed_;
  KneeModel base_;
};

/// `swingsim simulate`'s options: the default integrator and the energy bookkeeping it turns
/// on, so every swing of a tuning is the one simulate gives for the same files (the
/// bookkeeping's extra states move the integrator's steps: without it P1's swing time differs
/// by ~4e-5 s).
SwingOptions makeTuningSwingOptions();

}  // namespace swingsim
