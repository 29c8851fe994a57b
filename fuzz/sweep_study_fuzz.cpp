// libFuzzer target: knee-axis sweep study YAML (studies/burkett2004.yaml) through
// parseSweepStudy, then the lowering grid of each participant (what runSweep builds first).
#include "fuzz_common.h"
#include "study/sweep_study.h"
#include "sweep/sweep.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    const SweepStudy study = parseSweepStudy(fuzz::asText(data, size), fuzz::sourcePath("studies/fuzz.yaml"));
    for (const auto& p : study.participants) sweepLowerings(study, p);
  });
  return 0;
}
