#include "identify/synthetic_swing.h"

#include "identify/bench_data.h"
#include "swing/knee_setup.h"
#include "swing/swing_simulation.h"

namespace swingsim {

SwingRecord makeSyntheticSwing(const SwingBase& base, const SwingModelParams& truth, const SwingCondition& condition,
                               double noise, std::uint64_t seed, double sampleInterval) {
  Participant measured = base.participant;  // the drive as recorded
  auto& h = measured.hipMoment;
  h.timeScale *= condition.timeScale;
  h.flexionAmplitude *= condition.amplitudeScale;
  h.extensionAmplitude *= condition.amplitudeScale;
  for (double& m : h.moments) m *= condition.amplitudeScale;
  SwingBase conditionBase = base;
  conditionBase.participant = measured;
  const SwingSetup setup = makeSwingSetup(applyParticipantEffects(measured, truth.effects),
                                          std::make_shared<const KneeLawSum>(makeSwingKneeLaw(conditionBase, truth)));
  // Simbody's own integrator: the diagnosis refits on the reference swing's Dormand-Prince,
  // so the truth shares neither equations nor integration code with it.
  SwingOptions options = makeSimbodyIntegratorOptions();
  options.sampleInterval = sampleInterval;
  const SwingResult result = simulateSwing(setup, options);
  const auto& tr = result.trajectory;
  SwingRecord r;
  r.stem = condition.name;
  NormalNoise kneeNoise(seed), hipNoise(seed ^ 0x9E3779B97F4A7C15ULL);
  for (std::size_t i = 0; i < tr.size(); ++i) {
    r.time.push_back(tr.time[i]);
    r.kneeFlexion.push_back(tr.kneeFlexion[i] + noise * kDegToRad * kneeNoise.next());
    // With a socket the lab's thigh is the socket's (identify/swing_model.h).
    const double thigh = tr.socket.empty() ? tr.hipFlexion[i] : tr.socket[i].calcSocketAngle(tr.hipFlexion[i]);
    r.hipFlexion.push_back(thigh + noise * kDegToRad * hipNoise.next());
    r.hipMoment.push_back(measured.hipMoment.calcMoment(tr.time[i]));
  }
  return r;
}

}  // namespace swingsim
