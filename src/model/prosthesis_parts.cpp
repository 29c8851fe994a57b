#include "model/prosthesis_parts.h"

#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

namespace {

/// A rigid part on a line: its mass, its COM's coordinate along the line and its inertia
/// about that COM.
struct LinePart {
  double mass, at, inertia;
};

/// The parts as one body: total mass, COM by mass, inertia about it (parallel axes).
LinePart combine(const std::vector<LinePart>& parts) {
  LinePart sum{0, 0, 0};
  for (const LinePart& p : parts) {
    sum.mass += p.mass;
    sum.at += p.mass * p.at;
  }
  sum.at /= sum.mass;
  for (const LinePart& p : parts) sum.inertia += p.inertia + p.mass * (p.at - sum.at) * (p.at - sum.at);
  return sum;
}

}  // namespace

const ProsthesisPart* PartsCatalogue::find(const std::string& id) const {
  for (const ProsthesisPart& p : parts)
    if (p.id == id) return &p;
  return nullptr;
}

const char* partCategoryKey(PartCategory c) {
  switch (c) {
    case PartCategory::kKnee:
      return "knee";
    case PartCategory::kPylon:
      return "pylon";
    case PartCategory::kAnkle:
      return "ankle";
    case PartCategory::kFoot:
      return "foot";
  }
  return "?";
}

const std::string& partId(const ProsthesisPartsChoice& choice, PartCategory category) {
  return partId(const_cast<ProsthesisPartsChoice&>(choice), category);
}

std::string& partId(ProsthesisPartsChoice& choice, PartCategory category) {
  switch (category) {
    case PartCategory::kKnee:
      return choice.knee;
    case PartCategory::kPylon:
      return choice.pylon;
    case PartCategory::kAnkle:
      return choice.ankle;
    case PartCategory::kFoot:
      break;
  }
  return choice.foot;
}

double calcPartCom(const ProsthesisPart& part, double footLength) {
  if (part.com) return *part.com;
  if (part.category == PartCategory::kFoot) return footLength / 3.0;
  return part.length / 2.0;
}

double calcPartInertia(const ProsthesisPart& part) {
  return part.inertia ? *part.inertia : part.mass * part.length * part.length / 12.0;
}

SegmentParams assembleShank(const ShankParts& given, double shankLength) {
  if (!given.knee && !given.pylon && !given.ankle) throw std::invalid_argument("a shank needs at least one part");
  std::vector<LinePart> parts;                                                  // positions in m below the knee axis
  const double top = given.knee ? given.knee->length : 0;                       // where the pylon starts
  const double bottom = shankLength - (given.ankle ? given.ankle->length : 0);  // where it ends
  if (!(bottom > top))
    throw std::invalid_argument("the knee and ankle units (" + formatNumber(top) + " m + " +
                                formatNumber(given.ankle ? given.ankle->length : 0) + " m) do not fit in the shank (" +
                                formatNumber(shankLength) + " m from knee axis to ankle)");
  if (given.knee) parts.push_back({given.knee->mass, calcPartCom(*given.knee), calcPartInertia(*given.knee)});
  if (given.ankle)
    parts.push_back({given.ankle->mass, shankLength - calcPartCom(*given.ankle), calcPartInertia(*given.ankle)});
  if (const ProsthesisPart* pylon = given.pylon) {
    const double span = bottom - top;
    if (pylon->maxLength && span > *pylon->maxLength)
      throw std::invalid_argument("the pylon " + pylon->id + " is sold up to " + formatNumber(*pylon->maxLength) +
                                  " m, shorter than the " + formatNumber(span) + " m it must span");
    const double mass = pylon->mass * span / pylon->length;
    parts.push_back({mass, (top + bottom) / 2, mass * span * span / 12});
  }
  const LinePart shank = combine(parts);
  SegmentParams s;
  s.length = shankLength;
  s.mass = shank.mass;
  s.comFromDistal = shankLength - shank.at;
  s.inertia = shank.inertia;
  return s;
}

SegmentParams assembleFoot(const ProsthesisPart& foot, double footLength, FootComFrom comFrom) {
  const double forward = calcPartCom(foot, footLength);
  if (!(forward >= 0 && forward <= footLength))
    throw std::invalid_argument("the foot " + foot.id + "'s COM, " + formatNumber(forward) +
                                " m forward of the ankle, is not on the foot (0.." + formatNumber(footLength) + " m)");
  SegmentParams s;
  s.length = footLength;
  s.mass = foot.mass;
  s.comFromDistal = comFrom == FootComFrom::kAnkle ? forward : footLength - forward;
  s.inertia = calcPartInertia(foot);
  return s;
}

}  // namespace swingsim
