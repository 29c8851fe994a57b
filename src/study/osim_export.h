#pragma once
// The simulated leg of a participant as an OpenSim 4 model (io/osim_model_writer.h): the one
// sequence behind `swingsim export-osim` and Python's swingsim.export_osim(), so both write
// the same text (docs/export-osim.md).
#include <optional>
#include <string>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {

/// What export-osim takes besides the participant and its knee model.
struct OsimExportOptions {
  char side = 'r';                 ///< 'r' or 'l': names as OpenSim's gait models for that leg
  double lowering = 0;             ///< m, the knee-axis lowering
  std::optional<AddedMass> added;  ///< an added shank mass, welded to the tibia
};

/// The .osim text of `participant` with `knee` its knee model (whose stop gives the knee's
/// range), as `options` asks; under a measured drive every coordinate starts at the record's
/// toe-off and a measured pelvis moves on a planar joint. `stoName` is the trajectory file
/// named in the header for OpenSim's File > Load Motion. Throws InputError for a leg the
/// lowering or the added mass does not fit.
std::string formatParticipantOsim(const Participant& participant, const KneeModel& knee,
                                  const OsimExportOptions& options, const std::string& stoName);
/// The right leg, no added mass.
std::string formatParticipantOsim(const Participant& participant, const KneeModel& knee, double lowering,
                                  const std::string& stoName);

}  // namespace swingsim
