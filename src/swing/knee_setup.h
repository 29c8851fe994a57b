#pragma once
// The complete knee law of a participant's prosthesis: the knee model's resisting law and
// hyperextension stop (models/*.yaml) plus the knee unit's friction Tc near extension
// (Burkett 2004 Table 2 and Fig. 1 "FRICTION").
#include "model/knee_model.h"
#include "knee/knee_friction.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// model.law + KneeFriction(participant.kneeFriction). `friction` overrides the friction
/// smoothing (the convergence study varies it).
KneeLawSum makeKneeLaw(const Participant& participant, const KneeModel& model,
                       const KneeFrictionParams* friction = nullptr);

}  // namespace swingsim
