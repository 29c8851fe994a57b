// libFuzzer target: knee model YAML (models/*.yaml) through parseKneeModel, which also
// constructs the laws (damping table, Mauch cylinder, hyperextension stop).
#include "fuzz_common.h"
#include "io/knee_model_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] { parseKneeModel(fuzz::asText(data, size), fuzz::sourcePath("models/fuzz.yaml")); });
  return 0;
}
