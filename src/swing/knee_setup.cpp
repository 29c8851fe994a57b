#include "swing/knee_setup.h"

#include <utility>

namespace swingsim {

KneeLawSum makeKneeLaw(const Participant& participant, const KneeModel& model, const KneeFrictionParams* friction) {
  KneeLawSum law = model.law;
  KneeFrictionParams params = friction ? *friction : KneeFrictionParams{};
  params.frictionMoment = participant.kneeFriction;
  if (params.frictionMoment > 0) law.add(std::make_unique<KneeFriction>(params));
  return law;
}

SwingSetup makeSwingSetup(Participant participant, std::shared_ptr<const KneeLaw> knee, double lowering,
                          const AddedMass& added) {
  SwingSetup setup;
  setup.participant = std::move(participant);
  setup.knee = std::move(knee);
  setup.lowering = lowering;
  setup.added = added;
  return setup;
}

SwingSetup makeSwingSetup(Participant participant, const KneeModel& model, double lowering, const AddedMass& added) {
  auto knee = std::make_shared<const KneeLawSum>(makeKneeLaw(participant, model));
  // The knee file actually used (an override such as `simulate --knee` replaces the
  // participant's): a late failure names it, not the participant's knee_model.
  if (!model.path.empty()) participant.kneeModelPath = model.path;
  return makeSwingSetup(std::move(participant), std::move(knee), lowering, added);
}

}  // namespace swingsim
