#include "model/knee_model.h"

#include <memory>

namespace swingsim {

KneeLawSum makeKneeModelLaw(const KneeModelSpec& spec) {
  KneeLawSum law;
  if (spec.kind == KneeModelKind::kDampingTable)
    law.add(std::make_unique<DampingTable>(spec.table));
  else if (spec.kind == KneeModelKind::kMauch)
    law.add(std::make_unique<MauchCylinder>(spec.cylinder));
  else
    law.add(std::make_unique<ImpedanceStateMachine>(spec.stateMachine));
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
