#include "leg/toe_off_state.h"

namespace swingsim {

MeasuredKneeStart calcMeasuredKneeStart(const std::string& path, const std::vector<double>& time,
                                        const std::vector<double>& kneeFlexion) {
  // The same smoother as the thigh's, through the knee's samples.
  ThighKinematics knee;
  knee.path = path;
  knee.time = time;
  knee.hipFlexion = kneeFlexion;
  const ThighMotion spline(knee);
  return {spline.calcAngle(0), spline.calcRate(0)};
}

bool startsKneeFromRecord(const Participant& p) {
  return p.drive == SwingDrive::kThighKinematics && p.initial.kneeStart == KneeStart::kMeasured &&
         !p.thighKinematics.kneeFlexion.empty();
}

InitialConditions calcToeOffState(const Participant& p, const ThighMotion* thigh) {
  InitialConditions initial = p.initial;
  if (thigh == nullptr) return initial;
  initial.hipFlexion = thigh->calcAngle(0);
  initial.hipFlexionRate = thigh->calcRate(0);
  if (startsKneeFromRecord(p)) {
    const ThighKinematics& k = p.thighKinematics;
    const MeasuredKneeStart knee = calcMeasuredKneeStart(k.path, k.time, k.kneeFlexion);
    initial.kneeFlexion = knee.kneeFlexion;
    initial.kneeFlexionRate = knee.kneeFlexionRate;
  }
  return initial;
}

}  // namespace swingsim
