// libFuzzer target: compare/diagnose study YAML (studies/diagnose-demo-*.yaml), both kinds,
// read as the CLI reads them (one reader for both kinds, then unknown keys).
#include "fuzz_common.h"
#include "io/yaml_reader.h"
#include "study/diagnosis_study.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    YamlMap yaml = YamlMap::loadString(fuzz::asText(data, size), fuzz::sourcePath("studies/fuzz.yaml"));
    readDiagnosisStudy(yaml);
    yaml.finish();
  });
  return 0;
}
