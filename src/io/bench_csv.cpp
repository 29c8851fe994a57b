#include "io/bench_csv.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "core/output_files.h"
#include "core/units.h"
#include "io/csv_table.h"
#include "numerics/sample_derivative.h"

namespace swingsim {

BenchData readBenchCsv(const std::string& path, std::size_t minRows) {
  CsvSpec spec;
  spec.required = {"time_s", "position_m", "force_N"};
  spec.strictlyIncreasing = "time_s";
  spec.minRows = std::max<std::size_t>(minRows, 3);
  spec.minStep = kMinSampleStep;
  spec.ranges = {{"time_s", kRecordTimeRange, "a sample time"}, {"force_N", kForceRange, "a force"}};
  const CsvTable table = readCsv(path, spec);
  BenchData d;
  d.path = path;
  d.stem = fileStem(path);
  d.time = table.column("time_s");
  d.position = table.column("position_m");
  d.force = table.column("force_N");
  const auto [lo, hi] = std::minmax_element(d.position.begin(), d.position.end());
  // A record whose piston never moves carries no information on k or c.
  constexpr double kMinStroke = 1e-9;  // m
  if (*hi - *lo < kMinStroke)
    throw InputError(path + ": position_m: the piston never moves (all " + std::to_string(d.position.size()) +
                     " rows are " + formatNumber(*lo) + " m); a fit needs a varying position");
  // A knee cylinder's stroke is a few centimetres: metres of travel are millimetres.
  constexpr double kMaxPistonPosition = 1.0;  // m
  if (std::max(std::fabs(*lo), std::fabs(*hi)) > kMaxPistonPosition)
    throw InputError(path + ": position_m: the piston reaches " +
                     formatNumber(std::fabs(*lo) > std::fabs(*hi) ? *lo : *hi) +
                     " m (a knee cylinder's stroke is a few "
                     "centimetres; more than " +
                     formatNumber(kMaxPistonPosition) + " m): the column looks like millimetres, expected metres");
  d.velocity = estimatePistonVelocity(d.time, d.position);
  return d;
}

KneeAngleStride readKneeAngleStride(const std::string& csvPath, int firstFrame, int lastFrame) {
  CsvSpec spec;
  spec.required = {"frame", "knee_deg"};
  spec.strictlyIncreasing = "frame";
  spec.ranges = {{"knee_deg", kJointAngleRange, "a knee angle"}};
  const CsvTable table = readCsv(csvPath, spec);
  const auto& frames = table.column("frame");
  const auto& knee = table.column("knee_deg");
  if (lastFrame - firstFrame < 8)
    throw InputError(csvPath + ": stride frames " + std::to_string(firstFrame) + "-" + std::to_string(lastFrame) +
                     ": need at least 8 frames per stride");
  KneeAngleStride stride;
  stride.source = csvPath;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (frames[i] >= firstFrame && frames[i] < lastFrame) stride.flexion.push_back(knee[i] * kDegToRad);
  }
  if (static_cast<int>(stride.flexion.size()) != lastFrame - firstFrame)
    throw InputError(csvPath + ": frame: frames " + std::to_string(firstFrame) + " to " + std::to_string(lastFrame) +
                     " are not all present (found " + std::to_string(stride.flexion.size()) + ")");
  return stride;
}

}  // namespace swingsim
