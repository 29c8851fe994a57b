#pragma once
// The simulated leg of a participant as an OpenSim 4 model (io/osim_model_writer.h), for
// Python's swingsim.export_osim(). The same model and header as `swingsim export-osim`
// (src/cli/export_osim_command.cpp, which keeps its own copy of these two steps until the
// export-osim --side work is merged; then it calls this).
#include <string>

#include "io/knee_model_loader.h"
#include "io/participant_loader.h"

namespace swingsim {

/// The .osim text of `participant` with its knee axis lowered `lowering` m and `knee` its
/// knee model (whose stop gives the knee's range); `stoName` is the trajectory file named in
/// the header for OpenSim's File > Load Motion. Throws InputError for a leg the lowering
/// does not fit.
std::string formatParticipantOsim(const Participant& participant, const KneeModel& knee, double lowering,
                                  const std::string& stoName);

}  // namespace swingsim
