#pragma once
// One swing as `swingsim simulate`, Python swingsim.simulate() and the server's
// /api/simulate and /api/export-osim run it: the options (an integrator at its converged
// accuracy unless told otherwise), the toe-off overrides the command line takes, the set-up
// and the run, and simulate's text summary. The callers add only their own reading and
// writing.
#include <optional>
#include <string>

#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// simulate's options: `integrator` (a key of integratorKeys(), already checked) at its
/// converged accuracy, `accuracy` over that where given; the stop-impact energy bookkeeping
/// on (one swing: it is cheap here).
SwingOptions makeSimulateOptions(const std::optional<std::string>& integrator, std::optional<double> accuracy);

/// What the command line may change in a participant's toe-off state; nullopt: the file's.
struct ToeOffOverrides {
  std::optional<double> hipFlexionRate;   ///< rad/s
  std::optional<double> kneeFlexionRate;  ///< rad/s
  std::optional<KneeStart> kneeStart;
};

/// `p` with the overrides applied. A knee rate under a measured thigh drive whose knee starts
/// from the record is refused (InputError naming `kneeRateName`, the option that gave it):
/// there the record sets the knee's rate.
void applyToeOffOverrides(Participant& p, const ToeOffOverrides& overrides, const std::string& kneeRateName);

/// A swing's set-up and its result.
struct SimulateRun {
  SwingSetup setup;
  SwingResult result;
};

/// Runs the swing `setup` describes.
SimulateRun runSimulate(SwingSetup setup, const SwingOptions& options);

/// Sets up and runs one swing of `participant` with `knee`, the knee axis lowered by
/// `lowering` (m) and `added` on the shank.
SimulateRun runSimulate(Participant participant, const KneeModel& knee, double lowering, const AddedMass& added,
                        const SwingOptions& options);

/// The text `swingsim simulate` prints for a run (the trajectory files' line apart): drive,
/// toe-off, swing time or why the trial ended, peak, bounce, stop impacts, toe clearance,
/// integrator and events.
std::string formatSimulateSummary(const SimulateRun& run, const KneeModel& knee, const SwingOptions& options);

}  // namespace swingsim
