#include "io/parts_catalogue_loader.h"

#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "io/yaml_archive.h"
#include "io/yaml_reader.h"

namespace swingsim {

namespace {

constexpr double kMaxPartMass = 10;     // kg: heavier than any prosthetic knee, foot or pylon
constexpr double kMaxPartLength = 1.5;  // m

std::string checkPartMass(double v) {
  if (!(v > 0)) return "must be positive";
  return v <= kMaxPartMass ? ""
                           : "expected a part's mass of at most " + formatNumber(kMaxPartMass) +
                                 " kg (is it in grams? the key is in kg)";
}

std::string checkPartLength(double v) {
  if (!(v > 0)) return "must be positive";
  return v <= kMaxPartLength
             ? ""
             : "expected at most " + formatNumber(kMaxPartLength) + " m (is it in millimetres? the key is in metres)";
}

void readOptional(YamlReadArchive& a, const char* key, std::optional<double>& v, const ValueCheck& check) {
  if (!a.has(key)) return;
  double x = 0;
  a.number(key, x, check);
  v = x;
}

// Each category's keys: its length, its COM (none for a pylon: the middle of its span) and
// the part the COM must lie on.
struct CategoryKeys {
  const char *length, *com, *part;
};
CategoryKeys keysOf(PartCategory c) {
  switch (c) {
    case PartCategory::kKnee:
      return {"axis_to_connector_m", "com_below_axis_m", "the knee unit, below its axis"};
    case PartCategory::kPylon:
      return {"length_m", "", "the pylon"};
    case PartCategory::kAnkle:
      return {"connector_to_ankle_m", "com_above_ankle_m", "the ankle unit, above the ankle"};
    case PartCategory::kFoot:
      return {"length_m", "com_forward_of_ankle_m", "the foot, forward of the ankle"};
  }
  return {"length_m", "", ""};
}

}  // namespace

// Found by the archive's namedMaps through argument-dependent lookup: not in the anonymous namespace.
void serialize(YamlReadArchive& a, ProsthesisPart& p) {
  std::vector<std::pair<std::string, PartCategory>> categories;
  for (PartCategory c : kPartCategories) categories.emplace_back(partCategoryKey(c), c);
  a.choice("category", p.category, categories);
  a.text("name", p.name);
  a.text("maker", p.maker);
  a.text("source", p.source);
  a.optionalText("notes", p.notes);
  a.number("mass_kg", p.mass, checkPartMass);
  const CategoryKeys keys = keysOf(p.category);
  a.number(keys.length, p.length, checkPartLength);
  if (p.category == PartCategory::kPylon) {
    readOptional(a, "max_length_m", p.maxLength, checkPartLength);
    return;
  }
  readOptional(a, keys.com, p.com, mustBeNonNegative);
  readOptional(a, "inertia_kgm2", p.inertia, mustBePositive);
  a.require(!p.com || *p.com <= p.length, keys.com,
            std::string("the COM must lie on ") + keys.part + " (0.." + formatNumber(p.length) + " m)",
            [&] { return formatNumber(*p.com); });
}

namespace {

PartsCatalogue readCatalogue(YamlMap& yaml) {
  PartsCatalogue c;
  c.path = yaml.path();
  YamlReadArchive a(yaml);
  a.namedMaps("parts", c.parts, &ProsthesisPart::id);
  a.require(!c.parts.empty(), "parts", "expected at least one part", [] { return std::string("none"); });
  yaml.finish();
  return c;
}

}  // namespace

std::string defaultPartsCataloguePath() { return std::string(SWINGSIM_SOURCE_DIR) + "/parts/prosthesis-parts.yaml"; }

PartsCatalogue loadPartsCatalogue(const std::string& path) {
  YamlMap yaml = YamlMap::loadFile(path);
  return readCatalogue(yaml);
}

PartsCatalogue parsePartsCatalogue(const std::string& text, const std::string& path) {
  YamlMap yaml = YamlMap::loadString(text, path);
  return readCatalogue(yaml);
}

std::string checkCataloguePart(const PartsCatalogue& catalogue, const std::string& id, PartCategory category) {
  const ProsthesisPart* part = catalogue.find(id);
  if (part && part->category == category) return "";
  std::string ids;
  for (const ProsthesisPart& p : catalogue.parts)
    if (p.category == category) ids += (ids.empty() ? "" : ", ") + p.id;
  return std::string("expected a ") + partCategoryKey(category) + " of " + catalogue.path + ", one of " +
         (ids.empty() ? "(none)" : ids) +
         (part ? std::string(" (it is a ") + partCategoryKey(part->category) + ")" : "");
}

}  // namespace swingsim
