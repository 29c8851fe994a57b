#include "model/knee_model.h"

#include <memory>

namespace swingsim {

namespace {

// The resisting law of each kind.
std::unique_ptr<KneeLaw> makeResistingLaw(const DampingTableKnee& k) { return std::make_unique<DampingTable>(k.table); }
std::unique_ptr<KneeLaw> makeResistingLaw(const MauchKnee& k) { return std::make_unique<MauchCylinder>(k.cylinder); }
std::unique_ptr<KneeLaw> makeResistingLaw(const ImpedanceStateMachineKnee& k) {
  return std::make_unique<ImpedanceStateMachine>(k.stateMachine);
}
std::unique_ptr<KneeLaw> makeResistingLaw(const PneumaticKnee& k) {
  return std::make_unique<PneumaticCylinder>(k.cylinder);
}

}  // namespace

const char* KneeModelSpec::kindKey() const {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kKey; }, kind);
}

KneeLawSum makeKneeModelLaw(const KneeModelSpec& spec) {
  KneeLawSum law;
  law.add(std::visit([](const auto& k) { return makeResistingLaw(k); }, spec.kind));
  if (spec.hasKneeEffects) {
    if (spec.kneeEffects.modelScale != 1.0) {
      KneeLawSum scaled;
      for (std::size_t i = 0; i < law.size(); ++i)
        scaled.add(std::make_unique<ScaledKneeLaw>(law.part(i), spec.kneeEffects.modelScale));
      law = scaled;
    }
    law.add(std::make_unique<KneeAddedEffects>(spec.kneeEffects));
    addKneeExpressionLaws(law, spec.kneeEffects);
  }
  law.add(std::make_unique<JointStop>(spec.stop));
  return law;
}

}  // namespace swingsim
