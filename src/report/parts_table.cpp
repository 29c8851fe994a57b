#include "report/parts_table.h"

#include "core/text_format.h"

namespace swingsim {

namespace {

// The length's meaning per category, for the column's note.
const char* lengthMeaning(PartCategory c) {
  switch (c) {
    case PartCategory::kKnee:
      return "axis to connector";
    case PartCategory::kPylon:
      return "tube the mass is for";
    case PartCategory::kAnkle:
      return "connector to ankle";
    case PartCategory::kFoot:
      return "heel to toe";
  }
  return "";
}

// The COM column: the catalogue's value or the assumption.
std::string comText(const ProsthesisPart& p) {
  switch (p.category) {
    case PartCategory::kPylon:
      return "middle of its span";
    case PartCategory::kFoot:
      return p.com ? fmt("%.0f mm forward of the ankle", *p.com * 1000) : "assumed 1/3 of ankle-to-toe";
    case PartCategory::kKnee:
      return p.com ? fmt("%.0f mm below the axis", *p.com * 1000) : "assumed at half its height";
    case PartCategory::kAnkle:
      return p.com ? fmt("%.0f mm above the ankle", *p.com * 1000) : "assumed at half its height";
  }
  return "";
}

}  // namespace

std::string formatPartsTable(const PartsCatalogue& catalogue, std::optional<PartCategory> category) {
  std::string out = "Prosthesis parts in " + catalogue.path + " (docs/parts.md)\n\n";
  out += fmt("%-24s %-6s %9s %10s  %s\n", "id", "kind", "mass kg", "length mm", "COM; inertia");
  for (const ProsthesisPart& p : catalogue.parts) {
    if (category && p.category != *category) continue;
    const std::string inertia =
        p.category == PartCategory::kPylon
            ? "uniform tube"
            : (p.inertia ? fmt("%.1f kg cm^2", *p.inertia * 1e4) : "assumed uniform rod over its length");
    out += fmt("%-24s %-6s %9.5g %10.0f  %s; %s\n", p.id.c_str(), partCategoryKey(p.category), p.mass, p.length * 1000,
               comText(p).c_str(), inertia.c_str());
    out += "    " + p.name + "; maker: " + p.maker + "; length: " + lengthMeaning(p.category) +
           (p.maxLength ? fmt(", sold up to %.0f mm", *p.maxLength * 1000) : "") + "\n";
    out += "    source: " + p.source + "\n";
    if (!p.notes.empty()) out += "    notes: " + p.notes + "\n";
  }
  return out;
}

}  // namespace swingsim
