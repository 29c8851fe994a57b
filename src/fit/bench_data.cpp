#include "fit/bench_data.h"

#include <algorithm>
#include <cmath>

#include "io/csv_table.h"
#include "io/input_error.h"
#include "io/output_files.h"

namespace swingsim {

BenchData readBenchCsv(const std::string& path, std::size_t minRows) {
  CsvSpec spec;
  spec.required = {"time_s", "position_m", "force_N"};
  spec.strictlyIncreasing = "time_s";
  spec.minRows = std::max<std::size_t>(minRows, 3);
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
  d.velocity = estimatePistonVelocity(d.time, d.position);
  return d;
}

std::vector<double> estimatePistonVelocity(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t n = t.size();
  std::vector<double> v(n, 0.0);
  if (n < 2) return v;
  v[0] = (x[1] - x[0]) / (t[1] - t[0]);
  v[n - 1] = (x[n - 1] - x[n - 2]) / (t[n - 1] - t[n - 2]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    // Second-order central difference on an uneven grid.
    const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
    v[i] = (h0 * h0 * (x[i + 1] - x[i]) + h1 * h1 * (x[i] - x[i - 1])) / (h0 * h1 * (h0 + h1));
  }
  return v;
}

CylinderTrace calcCylinderTrace(const MauchCylinder& cylinder, const std::vector<double>& time,
                                const std::vector<double>& x, const std::vector<double>& xd, double s2Start) {
  CylinderTrace tr;
  tr.latch = calcLatchHistory(time, x, xd, cylinder.params().switches, s2Start);
  tr.force.resize(time.size());
  // Piston acceleration only for an added inertia effect (the same difference estimate again).
  const std::vector<double> xdd =
      cylinder.params().effects.inertia && time.size() >= 2 ? estimatePistonVelocity(time, xd) : std::vector<double>(time.size(), 0.0);
  for (std::size_t i = 0; i < time.size(); ++i) {
    tr.force[i] = cylinder.calcForce(x[i], xd[i], xdd[i], tr.latch[i]);
    tr.switches.push_back(calcMauchSwitches(x[i], xd[i], tr.latch[i], cylinder.params().switches));
    tr.gates.push_back(cylinder.calcGates(tr.switches.back()));
  }
  return tr;
}

double NormalNoise::uniform() {
  // 53 random bits -> (0, 1), never 0 so the logarithm is finite.
  return (static_cast<double>(engine_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double NormalNoise::next() {
  if (haveSpare_) {
    haveSpare_ = false;
    return spare_;
  }
  constexpr double kTwoPi = 6.28318530717958647692;
  const double r = std::sqrt(-2.0 * std::log(uniform()));
  const double a = kTwoPi * uniform();
  spare_ = r * std::sin(a);
  haveSpare_ = true;
  return r * std::cos(a);
}

}  // namespace swingsim
