#pragma once
// The prosthesis parts catalogue (parts/prosthesis-parts.yaml; docs/parts.md): each part's
// category, published mass, length and source, read and checked like every other input.
#include <string>

#include "model/prosthesis_parts.h"

namespace swingsim {

/// The catalogue shipped with swingsim (parts/prosthesis-parts.yaml in the source tree).
std::string defaultPartsCataloguePath();

/// Reads a catalogue. Throws InputError (`file:line: key: ...`) on any bad input: an
/// unknown category or key, a mass or length out of range (grams for kg), a COM off its
/// part, no source.
PartsCatalogue loadPartsCatalogue(const std::string& path);
/// Same, from YAML text (tests).
PartsCatalogue parsePartsCatalogue(const std::string& text, const std::string& path);

/// "" if `catalogue` has a part `id` of `category`; else what was expected: the category
/// and its ids ("expected a knee of FILE, one of osl-knee, ...").
std::string checkCataloguePart(const PartsCatalogue& catalogue, const std::string& id, PartCategory category);

}  // namespace swingsim
