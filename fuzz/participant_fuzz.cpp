// libFuzzer target: participant YAML (participants/*.yaml) through parseParticipant, then
// the leg geometry and hip moment built from it, as `swingsim simulate` would.
#include "fuzz_common.h"
#include "io/participant_loader.h"
#include "model/hip_moment_profile.h"
#include "model/leg_parameters.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    const Participant p = parseParticipant(fuzz::asText(data, size), fuzz::sourcePath("participants/fuzz.yaml"));
    calcLegGeometry(p, 0.0, {});
    calcMaxLowering(p);
    p.hipMoment.validate();
  });
  return 0;
}
