#pragma once
// Measured and model over time, per record: the compared quantity (the swing's knee flexion)
// and the plant's second one (hip flexion) overlaid, and the knee moment the model applies
// against the measured (inverse-dynamics) one when the record has it. What a reader looks at
// first, before the residual panels (diagnosis_report.h) say where the difference sits.
#include <string>
#include <vector>

#include "identify/comparison.h"

namespace swingsim {

/// Stacked panels for one record: measured and model `comparison.quantity` against time,
/// the secondary quantity if the record has its series, and `moment` (measured and model)
/// if not null.
std::string renderOverlaySvg(const RecordComparison& record, const Comparison& comparison,
                             const HeldBackComparison::Record* moment, const std::string& momentUnit,
                             const std::string& title);

/// Writes `<prefix>-<stem>-overlay.svg` into `outDir` for every record of a comparison with a
/// secondary quantity (the swing; a bench record's force is already in its residual plot's
/// context), with the record's knee moment from `heldBack` (matched by stem) when given.
/// Returns the paths written.
std::vector<std::string> writeOverlayPlots(const std::string& outDir, const std::string& prefix,
                                           const Comparison& comparison, const HeldBackComparison* heldBack = nullptr);

}  // namespace swingsim
