// swingsim parts [--catalogue FILE] [--category knee|pylon|ankle|foot]
//
// Lists the prosthesis parts catalogue: the ids a participant's `prosthesis_parts:` and
// import-osim's --knee-part, --foot-part, ... name, with each part's published mass and its
// source (docs/parts.md).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "io/parts_catalogue_loader.h"
#include "report/parts_table.h"

namespace swingsim::cli {
namespace {

struct PartsArguments {
  std::optional<std::string> catalogue, category;
};

int runParts(const PartsArguments& a) {
  const PartsCatalogue catalogue = loadPartsCatalogue(a.catalogue.value_or(defaultPartsCataloguePath()));
  std::optional<PartCategory> category;
  for (PartCategory c : kPartCategories)
    if (a.category && *a.category == partCategoryKey(c)) category = c;
  std::printf("%s", formatPartsTable(catalogue, category).c_str());
  return 0;
}

}  // namespace

Command addPartsCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "parts", "list the prosthesis parts catalogue: knees, pylons, ankle units and feet by their published masses");
  auto a = std::make_shared<PartsArguments>();
  addTextOption(sub, "--catalogue", a->catalogue, "parts catalogue YAML (default parts/prosthesis-parts.yaml)", "FILE");
  addTextOption(sub, "--category", a->category, "list only this kind of part", "knee|pylon|ankle|foot")
      ->check(oneOf({"knee", "pylon", "ankle", "foot"}));
  return {sub, [a] { return runParts(*a); }};
}

}  // namespace swingsim::cli
