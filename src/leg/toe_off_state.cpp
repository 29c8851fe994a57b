#include "leg/toe_off_state.h"

namespace swingsim {

MeasuredKneeStart calcMeasuredKneeStart(const ThighKinematics& kinematics) {
  // The same smoother as the thigh's, through the knee's samples.
  ThighKinematics knee;
  knee.path = kinematics.path;
  knee.time = kinematics.time;
  knee.hipFlexion = kinematics.kneeFlexion;
  const ThighMotion spline(knee);
  return {spline.calcAngle(0), spline.calcRate(0)};
}

InitialConditions calcToeOffState(const Participant& p, const ThighMotion* thigh) {
  InitialConditions initial = p.initial;
  if (thigh == nullptr) return initial;
  initial.hipFlexion = thigh->calcAngle(0);
  initial.hipFlexionRate = thigh->calcRate(0);
  if (p.initial.kneeStart == KneeStart::kMeasured && !p.thighKinematics.kneeFlexion.empty()) {
    const MeasuredKneeStart knee = calcMeasuredKneeStart(p.thighKinematics);
    initial.kneeFlexion = knee.kneeFlexion;
    initial.kneeFlexionRate = knee.kneeFlexionRate;
  }
  return initial;
}

}  // namespace swingsim
