#pragma once
// One swing: build the leg for a participant and lowering, integrate from toe-off with
// Simbody, find the swing end by event handlers, and return times, events and trajectory.
#include <string>
#include <vector>

#include "knee/knee_law.h"
#include "leg/leg_parameters.h"

namespace swingsim {

/// Integrator settings. The defaults are the converged settings of the README's
/// convergence study (swing time converged to 0.1 ms).
struct SwingOptions {
  double accuracy = 1e-4;           ///< Simbody integrator relative accuracy
  double sampleInterval = 0.002;    ///< s between trajectory samples (Hermite-interpolated between steps: free)
  bool recordTrajectory = true;
  double eventWindow = 1e-5;        ///< s, required event localization window
};

struct SwingEvent {
  std::string name;  ///< thigh_at_target, knee_peak_flexion, knee_enters_zone, knee_leaves_zone, swing_end
  double time;       ///< s since toe-off
};

/// Sampled trajectory, SI units (rad, rad/s, N m, m).
struct SwingTrajectory {
  std::vector<double> time, hipFlexion, kneeFlexion, hipFlexionRate, kneeFlexionRate, hipMoment, kneeMoment;
  std::vector<double> kneeX, kneeY, ankleX, ankleY, toeX, toeY;  ///< ground frame, hip at (0, hipHeight)
  std::size_t size() const { return time.size(); }
};

struct SwingResult {
  double swingTime = 0;            ///< s: thigh at target AND knee back in the zone after its peak
  double peakKneeFlexion = 0;      ///< rad
  double peakKneeFlexionTime = 0;  ///< s
  bool bounce = false;             ///< knee left the zone again after entering it
  double minToeClearance = 0;      ///< m, lowest ankle or toe height above ground from peak knee flexion to the swing end
  std::vector<SwingEvent> events;
  SwingTrajectory trajectory;
  int steps = 0;                   ///< integrator steps taken
  int realizations = 0;            ///< system realizations the integrator asked for
};

/// The participant-level inputs one swing needs, after loading.
struct SwingSetup {
  Participant participant;
  const KneeLaw* knee = nullptr;  ///< full knee law (model + friction + stop)
  double lowering = 0;            ///< m
  AddedMass added;
};

/// Standing hip height used for toe clearance: 0.530 x height (Winter 2009, Table 4.1
/// segment lengths: greater trochanter at 0.530 H).
double calcHipHeight(const Participant& p);

/// Runs one swing. Throws RunError (with the time, the state and the likely cause) if the
/// integrator fails or the swing does not end within the time limit.
SwingResult simulateSwing(const SwingSetup& setup, const SwingOptions& options = {});

}  // namespace swingsim
