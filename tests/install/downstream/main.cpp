// swingsim_downstream PARTICIPANT.yaml: one swing of the participant at lowering 0, with the
// knee model the file names, simulated through the installed library as `swingsim simulate`
// does it; prints `swing_time_s <seconds, 17 significant digits>`.
#include <cstdio>
#include <exception>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: swingsim_downstream PARTICIPANT.yaml\n");
    return 2;
  }
  try {
    swingsim::Participant participant = swingsim::loadParticipant(argv[1]);
    const swingsim::KneeModel model = swingsim::loadKneeModel(participant.kneeModelPath);
    const swingsim::SwingSetup setup = swingsim::makeSwingSetup(std::move(participant), model);
    swingsim::SwingOptions options;
    options.trackImpactEnergy = true;  // as `swingsim simulate`
    const swingsim::SwingResult result = swingsim::simulateSwing(setup, options);
    if (result.trialEnd) {
      std::fprintf(stderr, "swingsim_downstream: the swing did not end (%s)\n", result.trialEnd->unmet.c_str());
      return 1;
    }
    std::printf("swing_time_s %.17g\n", result.swingTime);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swingsim_downstream: %s\n", e.what());
    return 1;
  }
  return 0;
}
