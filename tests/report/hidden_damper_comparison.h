#pragma once
// One swing of P1 with a hidden viscous knee damper (0.3 N m s/rad, seed 7), compared with
// the plain model: a comparison with a structured residual, for the report figures' tests.
#include <string>
#include <vector>

#include "identify/swing_plant.h"
#include "identify/synthetic_swing.h"
#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim::testing {

inline Comparison compareHiddenDamperSwing() {
  const std::string root = SWINGSIM_SOURCE_DIR;
  SwingBase base;
  base.participant = loadParticipant(root + "/participants/p1.yaml");
  base.knee = loadKneeModel(root + "/models/damping-table-default.yaml");
  SwingModelParams truth = addSwingEffect({}, EffectId::kKneeViscousDamping, 0);
  truth.effects.knee.viscousDamping = 0.3;
  const std::vector<SwingRecord> train = {makeSyntheticSwing(base, truth, {"normal", 1.0, 1.0}, 0.5, 7)};
  return SwingPlant(base, train, {}).compare(SwingModel(SwingModelParams{}));
}

}  // namespace swingsim::testing
