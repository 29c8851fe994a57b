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

  TunedSetting at(const std::vector<double>& values) const;
  /// One swing at `values`; safe from several threads. Throws RunError, InputError.
  SwingResult simulate(const std::vector<double>& values, const SwingOptions& options) const;
  const Participant& participant() const { return participant_; }

 private:
  Participant participant_;
  KneeModelKnobs kneeFile_;
  std::vector<TuningKnob> knobs_;
  double lowering_ = 0;
  AddedMass added_;
  std::vector<std::pair<std::string, double>> fixed_;
  KneeModel base_;
};

/// `swingsim simulate`'s options: the default integrator and the energy bookkeeping it turns
/// on, so every swing of a tuning is the one simulate gives for the same files (the
/// bookkeeping's extra states move the integrator's steps: without it P1's swing time differs
/// by ~4e-5 s).
SwingOptions makeTuningSwingOptions();

}  // namespace swingsim
