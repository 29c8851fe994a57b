#include "model/leg_parameters.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"

namespace swingsim {

double calcMaxLowering(const Participant& p) {
  double max = p.shank.length - p.minShankLength;
  if (p.comRule == ComRule::kFixedFromProximal) {
    // The shank COM stays at its distance below the knee: it must remain on the shank.
    max = std::min(max, p.shank.comFromDistal);
  }
  return std::max(0.0, max);
}

LegGeometry calcLegGeometry(const Participant& p, double lowering, const AddedMass& added) {
  if (!(lowering >= 0) || !std::isfinite(lowering)) {
    throw InputError(p.path + ": lowering: must be zero or positive (got " + formatNumber(lowering) + " m)");
  }
  const double maxLowering = calcMaxLowering(p);
  if (lowering > maxLowering + 1e-12) {
    throw InputError(p.path + ": lowering: " + formatNumber(lowering) + " m leaves no room for the shank of " + p.name +
                     " (shank " + formatNumber(p.shank.length) + " m, at most " +
                     formatNumber(std::floor(maxLowering * 1000) / 1000) + " m can be lowered with at least " +
                     formatNumber(p.minShankLength) + " m of shank and its COM on it) (got " + formatNumber(lowering) +
                     ")");
  }
  LegGeometry g{};
  g.thighLength = p.thigh.length + lowering;
  g.shankLength = p.shank.length - lowering;
  g.thighMass = p.thigh.mass;
  g.shankMass = p.shank.mass;
  g.thighInertia = p.thigh.inertia;
  g.shankInertia = p.shank.inertia;
  const double thighComStd = p.thigh.length - p.thigh.comFromDistal;
  const double shankComStd = p.shank.length - p.shank.comFromDistal;
  if (p.comRule == ComRule::kFixedFromProximal) {
    g.thighCom = thighComStd;
    g.shankCom = shankComStd;
  } else {
    g.thighCom = thighComStd / p.thigh.length * g.thighLength;
    g.shankCom = shankComStd / p.shank.length * g.shankLength;
  }
  g.footLength = p.foot.length;
  g.footMass = p.foot.mass;
  g.footInertia = p.foot.inertia;
  g.footComForward = p.footComFrom == FootComFrom::kToe ? p.foot.length - p.foot.comFromDistal : p.foot.comFromDistal;
  if (added.mass < 0 || added.distanceBelowKnee < 0 || added.distanceBelowKnee > g.shankLength) {
    throw InputError(p.path + ": added mass: must be >= 0 kg at 0.." + formatNumber(g.shankLength) +
                     " m below the knee (got " + formatNumber(added.mass) + " kg at " +
                     formatNumber(added.distanceBelowKnee) + " m)");
  }
  // A weight strapped to a shank is a few kilograms; more than a whole body is a unit
  // mistake (grams) or a typo, and would reach Simbody as a NaN inertia.
  constexpr double kMaxAddedMass = 150;  // kg
  if (added.mass > kMaxAddedMass) {
    throw InputError(p.path + ": added mass: expected at most " + formatNumber(kMaxAddedMass) +
                     " kg (heavier than a whole body: is it in grams?) (got " + formatNumber(added.mass) + " kg)");
  }
  g.added = added;
  if (p.socket) {
    g.socket = p.socket;
    g.socketPivotBelowHip = p.thigh.length - p.socket->pivotAboveKnee;
    const double comBelowHip = g.socketPivotBelowHip - p.socket->comAbovePivot;
    if (!(g.socketPivotBelowHip > 0) || comBelowHip < 0)
      throw InputError(p.path +
                       ": socket: pivot_above_knee_m and com_above_pivot_m must put the pivot and the socket's "
                       "COM on the thigh (thigh " +
                       formatNumber(p.thigh.length) + " m; got the pivot " + formatNumber(g.socketPivotBelowHip) +
                       " m and the COM " + formatNumber(comBelowHip) + " m below the hip)");
    if (!(p.socket->mass < p.thigh.mass))
      throw InputError(p.path + ": socket: mass_kg must be less than the thigh's " + formatNumber(p.thigh.mass) +
                       " kg, which includes it (got " + formatNumber(p.socket->mass) + " kg)");
    if (!(calcResidualLimb(g).inertia > 0))
      throw InputError(p.path + ": socket: the socket's inertia (inertia_kg_m2 " + formatNumber(p.socket->inertia) +
                       " kg m^2 at " + formatNumber(comBelowHip) + " m below the hip) is more than the thigh's (" +
                       formatNumber(g.thighInertia) + " kg m^2 about its COM), which includes it");
  }
  return g;
}

SegmentMassProperties calcResidualLimb(const LegGeometry& g) {
  if (!g.socket) return {g.thighMass, g.thighCom, g.thighInertia};
  const SocketCompliance& s = *g.socket;
  const double socketCom = g.socketPivotBelowHip - s.comAbovePivot;
  SegmentMassProperties r{};
  r.mass = g.thighMass - s.mass;
  r.com = (g.thighMass * g.thighCom - s.mass * socketCom) / r.mass;
  // Inertias about the hip subtract; then back to the residual limb's own COM.
  const double aboutHip =
      g.thighInertia + g.thighMass * g.thighCom * g.thighCom - (s.inertia + s.mass * socketCom * socketCom);
  r.inertia = aboutHip - r.mass * r.com * r.com;
  return r;
}

PlanarPose calcPlanarPoseXY(const LegGeometry& g, double hipHeight, double hipFlexion, double kneeFlexion,
                            const SocketDeflection& socket) {
  const SocketDeflection d = g.socket ? socket : SocketDeflection{};
  const double socketAngle = d.calcSocketAngle(hipFlexion);  // the socket's line from hanging straight down
  const double shank = socketAngle - kneeFlexion;            // absolute shank angle from the downward vertical
  // The knee: down the thigh to the socket's pivot (moved by the piston), then down the socket.
  const double toPivot = g.socket ? g.socketPivotBelowHip + d.piston : g.thighLength;
  const double pivotToKnee = g.socket ? g.thighLength - g.socketPivotBelowHip : 0;
  PlanarPose p{};
  p.hip[0] = 0;
  p.hip[1] = hipHeight;
  p.knee[0] = toPivot * std::sin(hipFlexion) + pivotToKnee * std::sin(socketAngle);
  p.knee[1] = hipHeight - toPivot * std::cos(hipFlexion) - pivotToKnee * std::cos(socketAngle);
  p.ankle[0] = p.knee[0] + g.shankLength * std::sin(shank);
  p.ankle[1] = p.knee[1] - g.shankLength * std::cos(shank);
  p.toe[0] = p.ankle[0] + g.footLength * std::cos(shank);
  p.toe[1] = p.ankle[1] + g.footLength * std::sin(shank);
  return p;
}

}  // namespace swingsim
