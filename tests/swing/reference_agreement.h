#pragma once
// One swing by Simbody and by the independent reference integrator, both far tighter than
// the agreement asked for, and how far apart they are: a disagreement means different
// equations (as tests/swing/reference_swing_test.cpp; docs/verification.md).
#include <algorithm>
#include <cmath>
#include <memory>

#include "model/leg_parameters.h"
#include "swing/knee_setup.h"
#include "swing/reference_swing.h"
#include "swing/swing_simulation.h"

namespace swingsim::testing {

constexpr double kSimbodyAccuracy = 1e-10;
constexpr double kReferenceTol = 1e-11;
constexpr double kAngleTol = 1e-6;      // rad
constexpr double kEventWindow = 1e-9;   // s
constexpr double kSwingTimeTol = 1e-6;  // s

struct ReferenceAgreement {
  double maxHipDiff = 0, maxKneeDiff = 0;  ///< rad, over Simbody's samples
  SwingResult sim;                         ///< Simbody's swing at kSimbodyAccuracy
  ReferenceSwingEnd end;                   ///< the reference's swing end
};

/// Participant `p`'s swing at lowering 0 with knee law `law`, both ways.
inline ReferenceAgreement compareWithReference(const Participant& p, const std::shared_ptr<const KneeLawSum>& law) {
  SwingOptions options = makeSimbodyIntegratorOptions(kSimbodyAccuracy);
  options.sampleInterval = 0.002;
  options.eventWindow = kEventWindow;
  ReferenceAgreement a;
  a.sim = simulateSwing(makeSwingSetup(p, law, 0.0), options);
  const ReferenceSwing reference(calcLegGeometry(p, 0.0), *law, p.hipMoment, p.hipRange);
  const ReferenceTrajectory tr = reference.integrate(p.initial, a.sim.trajectory.time, kReferenceTol, kReferenceTol);
  for (std::size_t i = 0; i < tr.size(); ++i) {
    a.maxHipDiff = std::max(a.maxHipDiff, std::abs(tr.hipFlexion[i] - a.sim.trajectory.hipFlexion[i]));
    a.maxKneeDiff = std::max(a.maxKneeDiff, std::abs(tr.kneeFlexion[i] - a.sim.trajectory.kneeFlexion[i]));
  }
  a.end = reference.calcSwingEnd(p.initial, p.swingEnd, kReferenceTol, kReferenceTol);
  return a;
}

}  // namespace swingsim::testing
