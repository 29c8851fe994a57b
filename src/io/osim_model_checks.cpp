#include "io/osim_model_checks.h"

#include <cmath>
#include <map>

#include "core/input_error.h"
#include "io/participant_loader.h"

namespace swingsim {

namespace {

// Height from the leg's lengths: the participant file's range.
constexpr double kMinHeight = 0.5, kMaxHeight = 2.6;  // m

std::string where(const std::string& path, const OsimBody& b) {
  return formatOsimElement(path, "Body", b.name, b.line);
}
std::string where(const std::string& path, const OsimJoint& j) {
  return formatOsimElement(path, j.type, j.name, j.line);
}

// "(is the model in millimetres? ...)" when `length` is about 1000x a real segment.
std::string millimetreHint(double length) {
  return length > kMaxSegmentLength ? " (is the model in millimetres? OpenSim lengths are in metres)" : "";
}

// A segment between two joint centres: its length, then its COM along it.
void checkSegment(const std::string& path, const std::string& segment, const SegmentParams& s,
                  const OsimJoint& proximal, const OsimJoint& distal, const OsimBody& body) {
  if (!(s.length > 0) || s.length > kMaxSegmentLength)
    throw InputError(where(path, distal) + "the " + segment + ", from the " + proximal.name + " centre to the " +
                     distal.name + " centre: expected a length above 0 and at most " + formatNumber(kMaxSegmentLength) +
                     " m" + millimetreHint(s.length) + " (got " + formatNumber(s.length) + " m)");
  // The body's own mass: a --shank-mass-kg is the command line's, checked with the participant.
  if (body.mass > kMaxSegmentMass)
    throw InputError(where(path, body) + "<mass>: expected at most " + formatNumber(kMaxSegmentMass) + " kg for the " +
                     segment + " (is the model in grams? OpenSim masses are in kg) (got " + formatNumber(body.mass) +
                     ")");
  if (!(s.comFromDistal >= 0 && s.comFromDistal <= s.length))
    throw InputError(where(path, body) + "<mass_center>: expected the COM on the " + segment + ", 0 to " +
                     formatNumber(s.length) + " m from the " + distal.name + " centre along it (got " +
                     formatNumber(s.comFromDistal) + " m)");
  if (!(s.inertia > 0))
    throw InputError(where(path, body) + "<inertia>: expected a positive Izz for the " + segment + " (got " +
                     formatNumber(s.inertia) + " kg m^2)");
}

// The foot: its length (from the toes unless --foot-length-m), its COM on it, its inertia.
void checkFoot(const std::string& path, const OsimLegSources& s, const SegmentParams& foot) {
  const std::string lengthFrom = s.footLengthGiven ? "--foot-length-m" : "the ankle to the toe tip";
  if (!s.footLengthGiven && (!(foot.length > 0) || foot.length > kMaxSegmentLength))
    throw InputError(where(path, *s.mtp) + "the foot, " + lengthFrom + " (the " + s.mtp->name +
                     " centre and the toes' COM): expected a length above 0 and at most " +
                     formatNumber(kMaxSegmentLength) + " m" + millimetreHint(foot.length) + " (got " +
                     formatNumber(foot.length) + " m)");
  if (!(foot.comFromDistal >= 0 && foot.comFromDistal <= foot.length))
    throw InputError(where(path, *s.talus) + "<mass_center>: expected the foot's combined COM on the foot, 0 to " +
                     formatNumber(foot.length) + " m forward of the " + s.ankle->name +
                     " centre (length: " + lengthFrom + ") (got " + formatNumber(foot.comFromDistal) + " m)");
  if (!(foot.inertia > 0))
    throw InputError(where(path, *s.talus) + "<inertia>: expected a positive Izz for the foot (got " +
                     formatNumber(foot.inertia) + " kg m^2)");
}

}  // namespace

std::string formatOsimElement(const std::string& path, const std::string& type, const std::string& name, int line) {
  return path + ":" + std::to_string(line) + ": <" + type + " name=\"" + name + "\">: ";
}

void checkOsimModelNames(const OsimModel& m) {
  std::map<std::string, const OsimBody*> bodies;
  for (const auto& b : m.bodies)
    if (const auto [it, added] = bodies.emplace(b.name, &b); !added)
      throw InputError(where(m.path, b) + "expected each body name once in the BodySet (got a second " + b.name +
                       "; the first is at line " + std::to_string(it->second->line) + ")");
  std::map<std::string, const OsimJoint*> joints, intoChild;
  for (const auto& j : m.joints) {
    if (const auto [it, added] = joints.emplace(j.name, &j); !added)
      throw InputError(where(m.path, j) + "expected each joint name once in the JointSet (got a second " + j.name +
                       "; the first is at line " + std::to_string(it->second->line) + ")");
    if (const auto [it, added] = intoChild.emplace(j.childBody, &j); !added)
      throw InputError(where(m.path, j) + "expected one joint into body " + j.childBody + " (got a second: <" +
                       it->second->type + " name=\"" + it->second->name + "\"> at line " +
                       std::to_string(it->second->line) + " is the first; which one places it is ambiguous)");
  }
}

void checkOsimBodyUnits(const std::string& path, const OsimBody& b) {
  if (b.mass > kMaxBodyMass)
    throw InputError(where(path, b) + "<mass>: expected at most " + formatNumber(kMaxBodyMass) +
                     " kg, heavier than a whole body (is the model in grams? OpenSim masses are in kg) (got " +
                     formatNumber(b.mass) + ")");
  for (int i = 0; i < 3; ++i)
    if (b.inertia(i, i) < 0)
      throw InputError(where(path, b) + "<inertia>: expected moments of inertia >= 0 kg m^2 (got " +
                       formatNumber(b.inertia(i, i)) + " as I" + std::string(2, "xyz"[i]) + ")");
}

void checkOsimLeg(const OsimModel& m, const OsimLegSources& s, const Participant& p) {
  checkSegment(m.path, "thigh", p.thigh, *s.hip, *s.knee, *s.femur);
  checkSegment(m.path, "shank", p.shank, *s.knee, *s.ankle, *s.tibia);
  checkFoot(m.path, s, p.foot);
  if (p.hipOffsetInPelvis && (std::abs((*p.hipOffsetInPelvis)[0]) > kMaxSegmentLength ||
                              std::abs((*p.hipOffsetInPelvis)[1]) > kMaxSegmentLength))
    throw InputError(where(m.path, *s.hip) + "the hip centre in " + s.hip->parentBody + ": expected x and y within " +
                     formatNumber(kMaxSegmentLength) + " m" + millimetreHint(kMaxSegmentLength + 1) + " (got " +
                     formatNumber((*p.hipOffsetInPelvis)[0]) + ", " + formatNumber((*p.hipOffsetInPelvis)[1]) + ")");
  if (!s.heightGiven && !(p.height > kMinHeight && p.height < kMaxHeight))
    throw InputError(where(m.path, *s.ankle) + "the standing height from the thigh and shank, (" +
                     formatNumber(p.thigh.length) + " + " + formatNumber(p.shank.length) + ") / 0.491 m: expected " +
                     formatNumber(kMinHeight) + " to " + formatNumber(kMaxHeight) + " m (got " +
                     formatNumber(p.height) + "; give --height-m if the model is not of an adult)");
  if (p.bodyMass > kMaxBodyMass)
    throw InputError(m.path + ":" + std::to_string(m.bodySetLine) +
                     ": <BodySet>: the sum of every body's <mass>: expected at most " + formatNumber(kMaxBodyMass) +
                     " kg (is the model in grams? OpenSim masses are in kg) (got " + formatNumber(p.bodyMass) + ")");
}

}  // namespace swingsim
