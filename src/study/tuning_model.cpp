#include "study/tuning_model.h"

#include "core/input_error.h"
#include "study/tuning_study.h"
#include "swing/knee_setup.h"

namespace swingsim {
namespace {

// The fixed settings' keys and values, then the knee knobs' (a fixed key that is also a knob is left out).
std::pair<std::vector<std::string>, std::vector<double>> listFixedSettings(
    const std::vector<std::pair<std::string, double>>& fixed, const std::vector<TuningKnob>& knobs) {
  std::vector<std::string> keys;
  std::vector<double> values;
  for (const auto& [key, value] : fixed) {
    bool isKnob = false;
    for (const TuningKnob& k : knobs) isKnob = isKnob || k.key == key;
    if (isKnob) continue;
    keys.push_back(key);
    values.push_back(value);
  }
  return {keys, values};
}

// Leg knob `key` at `value` into the lowering or the added mass (another key: nothing).
void applyLegKnob(const std::string& key, double value, double& lowering, AddedMass& added) {
  if (key == kLoweringKnob) lowering = value;
  if (key == kAddedMassKnob) added.mass = value;
  if (key == kAddedMassDistanceKnob) added.distanceBelowKnee = value;
}

}  // namespace

bool isLegTuningKnob(const std::string& key) {
  return key == kLoweringKnob || key == kAddedMassKnob || key == kAddedMassDistanceKnob;
}

void checkLegAtKnob(const Participant& p, double lowering, AddedMass added, const std::string& key, double value) {
  applyLegKnob(key, value, lowering, added);
  if (added.mass < 0) throw InputError("an added mass must not be negative");
  if (added.distanceBelowKnee < 0)
    throw InputError("an added mass's position must not be negative (it is below the knee)");
  if (lowering < 0)
    throw InputError("a lowering must not be negative (the knee axis moves down from the standard location)");
  calcLegGeometry(p, lowering, added);
}

TuningModel::TuningModel(Participant participant, KneeModelKnobs knee, std::vector<TuningKnob> knobs, double lowering,
                         AddedMass added, std::vector<std::pair<std::string, double>> fixedKneeSettings)
    : participant_(std::move(participant)),
      kneeFile_(std::move(knee)),
      knobs_(std::move(knobs)),
      lowering_(lowering),
      added_(added),
      fixed_(listFixedSettings(fixedKneeSettings, knobs_)) {
  base_ = fixed_.first.empty() ? kneeFile_.load() : kneeFile_.make(fixed_.first, fixed_.second);
}

TunedSetting TuningModel::at(const std::vector<double>& values) const {
  TunedSetting t;
  t.lowering = lowering_;
  t.added = added_;
  auto [keys, kneeValues] = fixed_;
  bool kneeKnob = false;
  for (std::size_t i = 0; i < values.size() && i < knobs_.size(); ++i) {
    const std::string& key = knobs_[i].key;
    applyLegKnob(key, values[i], t.lowering, t.added);
    if (isLegTuningKnob(key)) continue;
    keys.push_back(key);
    kneeValues.push_back(values[i]);
    kneeKnob = true;
  }
  t.knee = kneeKnob ? kneeFile_.make(keys, kneeValues) : base_;
  return t;
}

void TuningModel::checkKnobRanges() const {
  std::vector<double> values;
  for (const TuningKnob& k : knobs_) values.push_back(k.lower);
  for (std::size_t i = 0; i < knobs_.size(); ++i) {
    const TuningKnob& k = knobs_[i];
    for (const double end : {k.lower, k.upper}) {
      std::vector<double> at = values;
      at[i] = end;
      try {
        if (isLegTuningKnob(k.key))
          checkLegAtKnob(participant_, lowering_, added_, k.key, end);
        else
          this->at(at);
      } catch (const InputError& e) {
        throw InputError(k.key + ": expected a range the " + (isLegTuningKnob(k.key) ? "leg" : "knee model") +
                         " accepts (got " + formatNumber(end) + ": " + e.what() + ")");
      }
    }
  }
}

SwingResult TuningModel::simulate(const std::vector<double>& values, const SwingOptions& options) const {
  const TunedSetting t = at(values);
  return simulateSwing(makeSwingSetup(participant_, t.knee, t.lowering, t.added), options);
}

SwingOptions makeTuningSwingOptions() {
  SwingOptions o;
  o.trackImpactEnergy = true;
  return o;
}

}  // namespace swingsim
