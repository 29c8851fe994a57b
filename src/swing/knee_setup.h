#pragma once
// The complete knee law of a participant's prosthesis: the knee model's resisting law and
// hyperextension stop (models/*.yaml) plus the knee unit's friction Tc near extension
// (Burkett 2004 Table 2 and Fig. 1 "FRICTION"); and the one builder of a SwingSetup.
#include <memory>

#include "knee/knee_friction.h"
#include "model/knee_model.h"
#include "model/leg_parameters.h"
#include "swing/swing_simulation.h"

namespace swingsim {

/// model.law + KneeFriction(participant.kneeFriction). `friction` overrides the friction
/// smoothing (the convergence study varies it).
KneeLawSum makeKneeLaw(const Participant& participant, const KneeModel& model,
                       const KneeFrictionParams* friction = nullptr);

/// Every SwingSetup is made here: the participant, its full knee law (shared: one law may
/// serve many swings), the knee-axis lowering (m) and the added shank mass.
SwingSetup makeSwingSetup(Participant participant, std::shared_ptr<const KneeLaw> knee, double lowering = 0,
                          const AddedMass& added = {});
/// As above, with the participant's knee law built from `model` (makeKneeLaw); the setup's
/// participant.kneeModelPath becomes model.path, the file actually used.
SwingSetup makeSwingSetup(Participant participant, const KneeModel& model, double lowering = 0,
                          const AddedMass& added = {});

}  // namespace swingsim
