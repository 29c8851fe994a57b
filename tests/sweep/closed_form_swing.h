#pragma once
// A "swing" made by closed-form functions of two tuning knobs, for the tuning engine's tests
// (sweep/knee_tuning.h): what it must recover, report as missed, or reach along a limit is
// then known exactly.
#include <functional>
#include <vector>

#include "sweep/knee_tuning.h"

namespace swingsim {

/// Swing time (s), peak flexion (rad) and toe clearance (m) as functions of the two knobs;
/// no clearance function: 0.1 m everywhere.
struct ClosedFormSwing {
  std::function<double(double, double)> time, peak, clearance;
};

inline TuningEvaluator makeEvaluator(const ClosedFormSwing& f) {
  return [f](const std::vector<double>& x) {
    SwingResult r;
    r.swingTime = f.time(x[0], x[1]);
    r.peakKneeFlexion = KneePeak{f.peak(x[0], x[1]), 0.2};
    r.minToeClearance = f.clearance ? f.clearance(x[0], x[1]) : 0.1;
    return r;
  };
}

}  // namespace swingsim
