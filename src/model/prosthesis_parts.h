#pragma once
// Prosthesis parts by their catalogue masses (parts/prosthesis-parts.yaml; docs/parts.md):
// a knee unit, a pylon and a foot, and the shank and foot segments they make. No YAML here
// (io/parts_catalogue_loader.h reads the catalogue); the composition is rigid-body
// bookkeeping: masses add, COMs average by mass, inertias move to the common COM by the
// parallel-axis theorem.
#include <optional>
#include <string>
#include <vector>

#include "model/leg_parameters.h"

namespace swingsim {

/// What a part is: where it sits on the leg. Knee, pylon and ankle unit make the shank; the
/// foot (below the ankle joint) is the foot segment.
enum class PartCategory { kKnee, kPylon, kAnkle, kFoot };

/// One catalogue entry. Lengths are along the shank (knee, pylon) or along the foot.
struct ProsthesisPart {
  std::string id;  ///< the catalogue's key (what a participant names)
  PartCategory category = PartCategory::kKnee;
  std::string name, maker;
  std::string source;  ///< where the mass (and any other number) was published
  std::string notes;   ///< which numbers are derived or assumed, and how
  double mass = 0;     ///< kg, > 0 (a pylon: of the tube of `length`)
  /// m, > 0. Knee: the knee axis to its distal connector, where the pylon starts. Pylon: the
  /// length its `mass` was published for (the tube is cut to the leg: its mass per metre
  /// is what is used). Ankle unit: its proximal connector down to the ankle joint. Foot:
  /// heel to toe (the foot's size).
  double length = 0;
  /// Pylon: the longest tube sold, m (nullopt: not stated, no limit).
  std::optional<double> maxLength;
  /// Knee: m below the knee axis; ankle unit: m above the ankle joint; foot: m forward of
  /// the ankle. nullopt: the stated assumption (calcPartCom).
  std::optional<double> com;
  /// kg m^2 about the part's COM, sagittal. nullopt: a uniform rod over `length`.
  std::optional<double> inertia;
};

/// A catalogue of parts, in its file's order.
struct PartsCatalogue {
  std::string path;
  std::vector<ProsthesisPart> parts;
  /// The part with this id, or nullptr.
  const ProsthesisPart* find(const std::string& id) const;
};

/// Every category, in the order a participant's and a command's keys list them.
constexpr PartCategory kPartCategories[] = {PartCategory::kKnee, PartCategory::kPylon, PartCategory::kAnkle,
                                            PartCategory::kFoot};

/// The category's key in the catalogue (knee, pylon, ankle, foot).
const char* partCategoryKey(PartCategory c);

/// The id `choice` names for `category` ("" if none).
const std::string& partId(const ProsthesisPartsChoice& choice, PartCategory category);
std::string& partId(ProsthesisPartsChoice& choice, PartCategory category);

/// A part's COM: its catalogue value, or the assumption. A knee or an ankle unit without
/// one: half its height from its joint. A foot without one: a third of the ankle-to-toe length
/// `footLength` forward of the ankle (the anatomical foot's COM at half its heel-to-toe
/// length, Winter 2009 Table 4.1, with the ankle a quarter of it from the heel: an
/// assumption, plausible 0.2-0.45 of ankle-to-toe).
double calcPartCom(const ProsthesisPart& part, double footLength = 0);
/// A part's inertia about its COM: its catalogue value, or a uniform rod over `length`.
double calcPartInertia(const ProsthesisPart& part);

/// The shank parts a participant names (any may be null).
struct ShankParts {
  const ProsthesisPart* knee = nullptr;   ///< from the knee axis down
  const ProsthesisPart* pylon = nullptr;  ///< from the knee's connector to the ankle unit's (or the ankle)
  const ProsthesisPart* ankle = nullptr;  ///< from its connector down to the ankle joint
};

/// The shank made of `parts`, of length `shankLength` (knee axis to ankle joint); the
/// pylon's mass is its mass per metre times the length it spans. Its COM is given from the
/// distal end as SegmentParams holds it. Throws std::invalid_argument if the knee and ankle
/// units do not fit in the shank, the span is longer than the pylon is sold, or no part is
/// given.
SegmentParams assembleShank(const ShankParts& parts, double shankLength);

/// The foot segment of `foot` with ankle-to-toe length `footLength`, its COM measured from
/// the toe or from the ankle as the participant's `comFrom` says.
SegmentParams assembleFoot(const ProsthesisPart& foot, double footLength, FootComFrom comFrom);

}  // namespace swingsim
