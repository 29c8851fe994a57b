#pragma once
// The checks of an imported OpenSim model (io/osim_model.h), as strict as those of a
// participant file (io/participant_loader.h) and refused where the mistake is: each message
// starts `model.osim:LINE: <Element name="...">:`, never with the participant YAML that
// import-osim has not written yet (docs/import-osim.md, "What is checked").
#include <string>

#include "io/osim_model.h"
#include "model/leg_parameters.h"

namespace swingsim {

/// `path:line: <type name="name">: ` for a message about one element of a model.
std::string formatOsimElement(const std::string& path, const std::string& type, const std::string& name, int line);

/// Throws InputError at the second of two bodies or two joints of one name, and at the
/// second of two joints into one child body (which one places it would be a guess), naming
/// the first and its line.
void checkOsimModelNames(const OsimModel& model);

/// Throws InputError for a body no human body part can have in SI units: a mass above
/// kMaxBodyMass (a model in grams), or a negative moment of inertia, at its <Body>.
void checkOsimBodyUnits(const std::string& path, const OsimBody& body);

/// Where each number of an imported leg comes from in the model.
struct OsimLegSources {
  const OsimBody *femur, *tibia, *talus;
  const OsimJoint *hip, *knee, *ankle, *mtp;
  bool footLengthGiven = false;  ///< --foot-length-m, not the model's toes
  bool heightGiven = false;      ///< --height-m, not the leg's lengths
};

/// Throws InputError for a leg the participant file would refuse (a segment length out of
/// (0, kMaxSegmentLength] m, named as millimetres when it is 1000x too long; a COM off its
/// segment; a zero inertia; a hip offset, height or total mass out of range), at the joint
/// or body the number comes from.
void checkOsimLeg(const OsimModel& model, const OsimLegSources& sources, const Participant& leg);

}  // namespace swingsim
