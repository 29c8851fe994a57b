#include "swing/step_end.h"

#include <algorithm>

namespace swingsim {

using namespace SimTK;

StepEnd readStepEnd(const LegModel& leg, const State& s, bool trackEnergy) {
  const MultibodySystem& system = leg.getSystem();
  system.realize(s, Stage::Acceleration);
  StepEnd e{s.getTime(),
            leg.getHipFlexion(s),
            leg.getKneeFlexion(s),
            leg.getHipFlexionRate(s),
            leg.getKneeFlexionRate(s),
            leg.getHipFlexionAcceleration(s),
            leg.getKneeFlexionAcceleration(s),
            leg.calcHipMoment(s),
            leg.calcKneeMoment(s)};
  e.socket = leg.getSocketDeflection(s);
  if (trackEnergy) {
    e.kinetic = system.calcKineticEnergy(s);
    const int parts = std::min(leg.numKneeWorkParts(), kMaxWorkCauses - 1);
    for (int i = 0; i < parts; ++i) e.work[static_cast<std::size_t>(i)] = leg.getKneePartWork(s, i);
    e.numWork = parts;
    if (!leg.hasPrescribedThigh()) e.work[static_cast<std::size_t>(e.numWork++)] = leg.getHipWork(s);
  }
  return e;
}

void appendSample(SwingTrajectory& tr, const LegGeometry& g, double hipHeight, double t, double hip, double knee,
                  double hipRate, double kneeRate, double hipMoment, double kneeMoment,
                  const SocketDeflection& socket) {
  tr.time.push_back(t);
  tr.hipFlexion.push_back(hip);
  tr.kneeFlexion.push_back(knee);
  tr.hipFlexionRate.push_back(hipRate);
  tr.kneeFlexionRate.push_back(kneeRate);
  tr.hipMoment.push_back(hipMoment);
  tr.kneeMoment.push_back(kneeMoment);
  const PlanarPose pose = calcPlanarPoseXY(g, hipHeight, hip, knee, socket);
  tr.kneeX.push_back(pose.knee[0]);
  tr.kneeY.push_back(pose.knee[1]);
  tr.ankleX.push_back(pose.ankle[0]);
  tr.ankleY.push_back(pose.ankle[1]);
  tr.toeX.push_back(pose.toe[0]);
  tr.toeY.push_back(pose.toe[1]);
  if (g.socket) tr.socket.push_back(socket);
}

void appendSamples(const StepEnd& a, const StepEnd& b, double& nextSample, double interval, const LegGeometry& g,
                   double hipHeight, SwingTrajectory& tr) {
  const double h = b.t - a.t;
  auto hermite = [&](double y0, double d0, double y1, double d1, double s) {
    return calcHermite(y0, d0, y1, d1, h, s);
  };
  while (nextSample <= b.t + 1e-12 && h > 0) {
    const double s = std::clamp((nextSample - a.t) / h, 0.0, 1.0);
    const double hip = hermite(a.hip, a.hipRate, b.hip, b.hipRate, s);
    const double knee = hermite(a.knee, a.kneeRate, b.knee, b.kneeRate, s);
    appendSample(tr, g, hipHeight, nextSample, hip, knee, hermite(a.hipRate, a.hipAcc, b.hipRate, b.hipAcc, s),
                 hermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, s),
                 a.hipMoment + s * (b.hipMoment - a.hipMoment), a.kneeMoment + s * (b.kneeMoment - a.kneeMoment),
                 // The socket's millimetres: linear within a step (its steps are short, docs/socket.md).
                 {a.socket.piston + s * (b.socket.piston - a.socket.piston),
                  a.socket.rotation + s * (b.socket.rotation - a.socket.rotation)});
    nextSample += interval;
  }
}

std::optional<double> findKneeRisingAbove(const StepEnd& a, const StepEnd& b, double level) {
  if (a.knee > level) return a.t;  // already above at the step's start
  const double h = b.t - a.t;
  if (!(h > 0)) return b.knee > level ? std::optional<double>(b.t) : std::nullopt;
  auto above = [&](double s) { return calcHermite(a.knee, a.kneeRate, b.knee, b.kneeRate, h, s) - level; };
  double end = 1;  // where the interpolant is above the level, if anywhere
  if (!(b.knee > level)) {
    if (!(a.kneeRate > 0 && b.kneeRate < 0)) return std::nullopt;
    end = findRoot([&](double s) { return calcHermite(a.kneeRate, a.kneeAcc, b.kneeRate, b.kneeAcc, h, s); }, h);
    if (!(above(end) > 0)) return std::nullopt;
  }
  return a.t + findRoot(above, h, 0, end) * h;
}

}  // namespace swingsim
