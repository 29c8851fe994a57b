#pragma once
// The size of a diagnosis (rows of measured data its fits compare against, after any
// resampling) and a rough time for it, printed before the fit, and its limit: a
// 1,000,000-sample swing record or a 10,000-row measured sweep table ran for half a minute
// in silence (docs/robustness.md, "Large runs").
#include <cstddef>
#include <cstdint>
#include <string>

#include "identify/diagnosis_engine.h"

namespace swingsim {

/// The most rows a diagnosis runs on unless `diagnose --max-rows N` raises it, per plant:
/// swing records (samples, about 500 a swing at 1 kHz: about 3 min), a measured sweep table
/// (simulated swings per row and fit step; Burkett's Table 4 has 16: about 17 min) and bench
/// records (the CSV reader's own limit).
constexpr std::uint64_t kDefaultMaxSwingDiagnosisRows = 20000;
constexpr std::uint64_t kDefaultMaxSweepDiagnosisRows = 100;
constexpr std::uint64_t kDefaultMaxCylinderDiagnosisRows = 2000000;

/// How a command bounds a diagnosis.
struct DiagnosisRowLimit {
  std::uint64_t maxRows = 0;  ///< 0: the plant's default above
};

/// The plant's default limit.
std::uint64_t getDefaultMaxDiagnosisRows(PlantKind plant);

/// Prints "diagnose NAME: ROWS rows (RECORDS ...), about T" on stderr; InputError naming
/// `studyPath` and --max-rows if `rows` is above the limit.
void announceDiagnosisSize(const std::string& name, const std::string& studyPath, PlantKind plant, std::uint64_t rows,
                           std::size_t records, const DiagnosisRowLimit& limit);

}  // namespace swingsim
