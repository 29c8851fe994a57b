#pragma once
// Contacts of the knee with its hyperextension stop over a swing, and with
// SwingOptions::trackImpactEnergy where each impact's energy went.
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "swing/step_end.h"
#include "swing/swing_simulation.h"

namespace swingsim {

// Contacts of the knee with its hyperextension stop, from the step ends and their Hermite
// interpolants (as the fast path's events). It only reports; the swing end does not use it.
class StopImpactTracker {
 public:
  static constexpr std::size_t kMaxImpacts = 20;  // a knee resting on its stop could chatter

  StopImpactTracker(double engage, std::vector<std::string> causes) : engage_(engage), causes_(std::move(causes)) {}

  void onStep(const StepEnd& a, const StepEnd& b) {
    const double h = b.t - a.t;
    if (!(h > 0)) return;
    auto kneeAt = [&](double s) { return calcHermite(a.knee, a.kneeRate, b.knee, b.kneeRate, h, s); };
    auto rateAt = [&](double s) { return calcHermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, h, s); };
    auto witness = [&](double s) { return kneeAt(s) - engage_; };
    if (phase_ == kRebound && a.kneeRate > 0 && b.kneeRate <= 0) {
      const double top = findRoot(rateAt, h);
      closeRebound(a, b, top, kneeAt(top));
    }
    if (phase_ != kContact && a.knee >= engage_ && b.knee < engage_) {
      if (phase_ == kRebound) closeRebound(a, a, 0, a.knee);  // back on the stop before a top
      if (impacts_.size() >= kMaxImpacts) return;
      const double s0 = findRoot(witness, h);
      StopImpact impact;
      impact.time = a.t + s0 * h;
      impact.impactRate = -rateAt(s0);
      impact.kineticEnergy = lerp(a.kinetic, b.kinetic, s0);
      impacts_.push_back(impact);
      start_ = snapshot(a, b, s0);
      phase_ = kContact;
    }
    if (phase_ == kContact) {
      StopImpact& impact = impacts_.back();
      impact.maxPenetration = std::max(impact.maxPenetration, engage_ - b.knee);
      if (a.kneeRate < 0 && b.kneeRate > 0)
        impact.maxPenetration = std::max(impact.maxPenetration, engage_ - kneeAt(findRoot(rateAt, h)));
      if (a.knee < engage_ && b.knee >= engage_) {
        const double s1 = findRoot(witness, h);
        impact.reboundRate = std::max(0.0, rateAt(s1));
        impact.restitution = impact.impactRate > 0 ? impact.reboundRate / impact.impactRate : 0;
        phase_ = kRebound;
      }
    }
  }

  // The impacts, the last one closed at the final step end `last`.
  std::vector<StopImpact> finish(const StepEnd& last) {
    if (phase_ == kContact || phase_ == kRebound) closeRebound(last, last, 0, phase_ == kRebound ? last.knee : engage_);
    return impacts_;
  }

 private:
  enum Phase { kFree, kContact, kRebound };
  using Snapshot = std::array<double, kMaxWorkCauses>;
  static double lerp(double x0, double x1, double s) { return x0 + s * (x1 - x0); }
  static Snapshot snapshot(const StepEnd& a, const StepEnd& b, double s) {
    Snapshot w{};
    for (int i = 0; i < b.numWork; ++i)
      w[static_cast<std::size_t>(i)] =
          lerp(a.work[static_cast<std::size_t>(i)], b.work[static_cast<std::size_t>(i)], s);
    return w;
  }
  void closeRebound(const StepEnd& a, const StepEnd& b, double s, double height) {
    StopImpact& impact = impacts_.back();
    impact.reboundHeight = std::max(height, engage_);
    if (b.numWork > 0) {
      const Snapshot end = snapshot(a, b, s);
      for (int i = 0; i < b.numWork && static_cast<std::size_t>(i) < causes_.size(); ++i)
        impact.work.push_back({causes_[static_cast<std::size_t>(i)],
                               end[static_cast<std::size_t>(i)] - start_[static_cast<std::size_t>(i)]});
    }
    phase_ = kFree;
  }

  double engage_;
  std::vector<std::string> causes_;
  Phase phase_ = kFree;
  Snapshot start_{};
  std::vector<StopImpact> impacts_;
};

}  // namespace swingsim
