#include "report/parts_table.h"

#include <cstdio>

namespace swingsim {

namespace {

std::string fixed(double v, const char* format) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

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
      return p.com ? fixed(*p.com * 1000, "%.0f mm forward of the ankle") : "assumed 1/3 of ankle-to-toe";
    case PartCategory::kKnee:
      return p.com ? fixed(*p.com * 1000, "%.0f mm below the axis") : "assumed at half its height";
    case PartCategory::kAnkle:
      return p.com ? fixed(*p.com * 1000, "%.0f mm above the ankle") : "assumed at half its height";
  }
  return "";
}

}  // namespace

std::string formatPartsTable(const PartsCatalogue& catalogue, std::optional<PartCategory> category) {
  std::string out = "Prosthesis parts in " + catalogue.path + " (docs/parts.md)\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-24s %-6s %9s %10s  %s\n", "id", "kind", "mass kg", "length mm", "COM; inertia");
  out += line;
  for (const ProsthesisPart& p : catalogue.parts) {
    if (category && p.category != *category) continue;
    const std::string inertia =
        p.category == PartCategory::kPylon
            ? "uniform tube"
            : (p.inertia ? fixed(*p.inertia * 1e4, "%.1f kg cm^2") : "assumed uniform rod over its length");
    std::snprintf(line, sizeof line, "%-24s %-6s %9.5g %10.0f  %s; %s\n", p.id.c_str(), partCategoryKey(p.category),
                  p.mass, p.length * 1000, comText(p).c_str(), inertia.c_str());
    out += line;
    out += "    " + p.name + "; maker: " + p.maker + "; length: " + lengthMeaning(p.category) +
           (p.maxLength ? fixed(*p.maxLength * 1000, ", sold up to %.0f mm") : "") + "\n";
    out += "    source: " + p.source + "\n";
    if (!p.notes.empty()) out += "    notes: " + p.notes + "\n";
  }
  return out;
}

}  // namespace swingsim
