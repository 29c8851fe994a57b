// libFuzzer target: the OpenSim model reader (.osim XML, tinyxml2) and `swingsim
// import-osim` after it: the participant built from each leg, written as YAML and loaded
// back with the participant loader's checks, as the command does before it writes.
#include "fuzz_common.h"
#include "io/osim_model.h"
#include "io/participant_loader.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swingsim;
  fuzz::expectOnlyInputErrors([&] {
    const OsimModel model = parseOsimModel(fuzz::asText(data, size), "fuzz.osim");
    for (const char side : {'r', 'l'}) {
      fuzz::expectOnlyInputErrors([&] {
        OsimImportOptions options;
        options.side = side;
        options.kneeModelPath = fuzz::sourcePath("models/damping-table-default.yaml");
        const OsimParticipant imported = calcOsimParticipant(model, options);
        const std::string text =
            formatParticipantYaml(imported.participant, fuzz::sourcePath("participants"), imported.provenance);
        parseParticipant(text, fuzz::sourcePath("participants/fuzz.yaml"));
      });
    }
  });
  return 0;
}
