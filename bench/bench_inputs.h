#pragma once
// Inputs shared by the benchmarks and the convergence study: the bundled participants,
// their knee laws and the Burkett sweep, loaded from the source tree (so the bench runs
// from any directory).
#include <memory>
#include <string>
#include <vector>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"
#include "knee/knee_law.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim::bench {

/// Absolute path of a file in the source tree ("participants/p1.yaml").
inline std::string sourcePath(const std::string& relative) { return std::string(SWINGSIM_SOURCE_DIR) + "/" + relative; }

/// A participant with its complete knee law (model + friction + stop). The law lives
/// here, so a SwingSetup pointing at it stays valid while this object does.
struct LoadedParticipant {
  Participant participant;
  KneeModel model;
  std::shared_ptr<const KneeLawSum> knee;

  explicit LoadedParticipant(const std::string& yaml, const KneeFrictionParams* friction = nullptr)
      : participant(loadParticipant(sourcePath(yaml))),
        model(loadKneeModel(participant.kneeModelPath)),
        knee(std::make_shared<const KneeLawSum>(makeKneeLaw(participant, model, friction))) {}
  LoadedParticipant(const LoadedParticipant&) = delete;
  LoadedParticipant& operator=(const LoadedParticipant&) = delete;

  SwingSetup setup(double lowering = 0) const { return makeSwingSetup(participant, knee, lowering); }
};

inline const std::vector<std::string>& participantFiles() {
  static const std::vector<std::string> files = {"participants/p1.yaml", "participants/p2.yaml", "participants/p3.yaml",
                                                 "participants/p4.yaml"};
  return files;
}

/// The plain Burkett sweep: 4 participants x 21 lowerings, no Table 4 extras, no added mass.
inline SweepStudy plainBurkettSweep() {
  SweepStudy s = loadSweepStudy(sourcePath("studies/burkett2004.yaml"));
  s.addedMasses = {0.0};
  s.addedMassDistances.clear();
  s.includePublishedLowerings = false;
  return s;
}

/// `swingsim_bench --convergence [--out FILE.md]`: the convergence study (convergence_study.cpp).
int runConvergenceStudy(int argc, char** argv);

}  // namespace swingsim::bench
