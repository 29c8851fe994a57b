// libFuzzer target: participant YAML (participants/*.yaml) through parseParticipant, then
// the leg geometry and hip moment built from it, as `swingsim simulate` would; then the
// write path of `swingsim calibrate`: whatever loads must write, load back and write the
// same text (a difference aborts, so libFuzzer reports it).
#include "fuzz_common.h"
#include "io/participant_loader.h"
#include "model/hip_moment_profile.h"
#include "model/leg_parameters.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    const Participant p = parseParticipant(fuzz::asText(data, size), fuzz::sourcePath("participants/fuzz.yaml"));
    calcLegGeometry(p, 0.0, {});
    calcMaxLowering(p);
    p.hipMoment.validate();
    const std::string text = formatParticipantYaml(p, fuzz::sourcePath("participants"));
    const Participant back = parseParticipant(text, fuzz::sourcePath("participants/fuzz.yaml"));
    if (formatParticipantYaml(back, fuzz::sourcePath("participants")) != text) __builtin_trap();
  });
  return 0;
}
