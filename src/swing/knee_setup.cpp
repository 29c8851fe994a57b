#include "swing/knee_setup.h"

namespace swingsim {

KneeLawSum makeKneeLaw(const Participant& participant, const KneeModel& model,
                       const KneeFrictionParams* friction) {
  KneeLawSum law = model.law;
  KneeFrictionParams params = friction ? *friction : KneeFrictionParams{};
  params.frictionMoment = participant.kneeFriction;
  if (params.frictionMoment > 0) law.add(std::make_unique<KneeFriction>(params));
  return law;
}

}  // namespace swingsim
