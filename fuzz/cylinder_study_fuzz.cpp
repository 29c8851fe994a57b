// libFuzzer target: cylinder study YAML, both kinds (cylinder-bench for `swingsim generate`,
// cylinder-fit for `swingsim fit`), read the way those commands read them.
#include "fuzz_common.h"
#include "io/yaml_reader.h"
#include "study/cylinder_study.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    YamlMap yaml = YamlMap::loadString(fuzz::asText(data, size), fuzz::sourcePath("studies/fuzz.yaml"));
    if (!yaml.has("kind")) yaml.getString("kind");
    const std::string kind = yaml.getChoice("kind", {"cylinder-bench", "cylinder-fit"}, "");
    if (kind == "cylinder-bench")
      readCylinderBenchStudy(yaml);
    else
      readCylinderFitStudy(yaml);
    yaml.finish();
  });
  return 0;
}
