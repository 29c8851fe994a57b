#pragma once
// The prosthesis parts catalogue as a text table (`swingsim parts`): each part's id,
// category, mass, length, COM and inertia, with the stated assumption where the catalogue
// gives none, and its source.
#include <optional>
#include <string>

#include "model/prosthesis_parts.h"

namespace swingsim {

/// The table of `catalogue`'s parts (of `category` only, if given), one block per part.
std::string formatPartsTable(const PartsCatalogue& catalogue, std::optional<PartCategory> category = std::nullopt);

}  // namespace swingsim
