#pragma once
// The public OpenSim trials the swing-event tests read (sources: the README.md beside each
// folder), and the message of the InputError a call throws.
#include <functional>
#include <string>

#include "core/input_error.h"

namespace swingsim::testing {

inline const std::string kRoot = SWINGSIM_SOURCE_DIR;
// subject01's walk: one GRF file, three IK pipelines (Gait2392, Gait2354, Gait10dof18musc).
inline const std::string kWalkGrf = kRoot + "/studies/data/opensim-subject01/subject01_walk1_grf.mot";
inline const std::string kWalkIk2392 = kRoot + "/studies/data/opensim-subject01/gait2392_subject01_walk1_ik.mot";
inline const std::string kWalkIk2354 = kRoot + "/studies/data/opensim-subject01/gait2354_subject01_walk1_ik.mot";
inline const std::string kWalkIk10dof = kRoot + "/tests/data/opensim-gait10dof/subject01_walk_IK.mot";
// Two runners: Rajagopal's subject01 (knee_angle positive in flexion), Hamner's subject02.
inline const std::string kRajagopalRunIk = kRoot + "/tests/data/opensim-running/rajagopal_subject01_run_ik.mot";
inline const std::string kRajagopalRunGrf = kRoot + "/tests/data/opensim-running/rajagopal_grf_run.mot";
inline const std::string kHamnerRunIk = kRoot + "/tests/data/opensim-running/hamner_subject02_running_ik.mot";
inline const std::string kHamnerRunGrf = kRoot + "/tests/data/opensim-running/hamner_subject02_running_grf.mot";

/// The message of the InputError `f` throws, "(no InputError)" if none.
inline std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace swingsim::testing
