// The multi-start grid's costs |r|^2 of the projected residual, with the switch values
// shared between grid points computed once: in the latch history (calcLatchHistory, Eq. 6)
// the decay exp(-a h) of each sub-interval depends only on the velocity width and the latch
// rate, its target b only on the position width and xhy, and so do S1 and S8 of each
// sample; the grid has 6 and 20 such pairs for its 120 points, so the 120 latch histories
// need 11 times fewer tanh and exp. The arithmetic is calcLatchHistory's and
// calcMauchSwitches' (the fit's test checks the costs against calcProjectedResidual).
#include "identify/switch_grid_costs.h"

#include <cmath>
#include <utility>

#include "identify/projected_residual.h"

namespace swingsim {

namespace {

constexpr int kSubsteps = 10;  // calcLatchHistory's default, as buildRegressors uses it

using Pair = std::pair<double, double>;

// The index of `key` in `pairs`, appended if new (first-seen order).
std::size_t indexOf(std::vector<Pair>& pairs, Pair key) {
  for (std::size_t i = 0; i < pairs.size(); ++i)
    if (pairs[i] == key) return i;
  pairs.push_back(key);
  return pairs.size() - 1;
}

// The switch values of every distinct pair along the training set: per sub-interval the
// latch decay of each (velocity width, latch rate) and the target of each (position width,
// xhy); per sample S8 of each (position width, xhy) and S1 of each velocity width.
class SharedSwitchValues {
 public:
  SharedSwitchValues(const TrainingSet& set, const std::vector<MauchSwitchParams>& grid) : set_(set) {
    for (const auto& g : grid) {
      velocityOf.push_back(indexOf(velocityPairs_, {g.velocityWidth, g.latchRate}));
      positionOf.push_back(indexOf(positionPairs_, {g.positionWidth, g.hyperextensionPosition}));
      widthOf.push_back(indexOf(widths_, {g.velocityWidth, 0.0}));
    }
    std::size_t substeps = 0;
    for (const auto& d : set.files) substeps += kSubsteps * (d.time.size() > 0 ? d.time.size() - 1 : 0);
    const auto rows = static_cast<std::size_t>(set.rows);
    decay.assign(velocityPairs_.size(), std::vector<double>(substeps));
    target.assign(positionPairs_.size(), std::vector<double>(substeps));
    s1.assign(widths_.size(), std::vector<double>(rows));
    s8.assign(positionPairs_.size(), std::vector<double>(rows));
  }

  // Tasks first, first + step, ...: each velocity pair's decays, each position pair's
  // targets and S8, each width's S1.
  void fill(std::size_t first, std::size_t step) {
    const std::size_t tasks = velocityPairs_.size() + 2 * positionPairs_.size() + widths_.size();
    for (std::size_t task = first; task < tasks; task += step) fillTask(task);
  }

  std::vector<std::size_t> velocityOf, positionOf, widthOf;  // per grid point, its pairs' indices
  std::vector<std::vector<double>> decay, target, s1, s8;

 private:
  void fillTask(std::size_t task) {
    const std::size_t nv = velocityPairs_.size(), np = positionPairs_.size();
    std::size_t k = 0, r = 0;
    for (const auto& d : set_.files) {
      for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
        if (task >= nv + 2 * np) {
          const double vw = widths_[task - nv - 2 * np].first;
          s1[task - nv - 2 * np][r] = 0.5 + 0.5 * std::tanh(d.velocity[i] / vw);
          continue;
        }
        if (task >= nv + np) {
          const auto [pw, xhy] = positionPairs_[task - nv - np];
          s8[task - nv - np][r] = 0.5 + 0.5 * std::tanh((d.position[i] - xhy) / pw);
          continue;
        }
        if (i == 0) continue;
        const double h = (d.time[i] - d.time[i - 1]) / kSubsteps;
        for (int j = 0; j < kSubsteps; ++j, ++k) {
          const double w = (j + 0.5) / kSubsteps;
          if (task < nv) {
            const auto [vw, rate] = velocityPairs_[task];
            const double vm = d.velocity[i - 1] + w * (d.velocity[i] - d.velocity[i - 1]);
            const double a = rate * (0.5 - 0.5 * std::tanh(vm / vw));
            decay[task][k] = std::exp(-a * h);
          } else {
            const auto [pw, xhy] = positionPairs_[task - nv];
            const double xm = d.position[i - 1] + w * (d.position[i] - d.position[i - 1]);
            target[task - nv][k] = 0.5 - 0.5 * std::tanh((xm - xhy) / pw);
          }
        }
      }
    }
  }

  const TrainingSet& set_;
  std::vector<Pair> velocityPairs_, positionPairs_, widths_;
};

// The regressors of grid point g from the shared values: the latch history s2 = b + (s2 - b) E
// sub-interval by sub-interval, the gates, and the added effects' columns (which do not
// depend on the switch constants).
void buildGridRegressors(const MauchCylinder& cylinder, const TrainingSet& set, const SharedSwitchValues& shared,
                         std::size_t g, Eigen::MatrixXd& Xg) {
  const int p = cylinder.numCoefficients(), numGates = cylinder.numPhaseGates();
  const std::vector<double>&E = shared.decay[shared.velocityOf[g]], &B = shared.target[shared.positionOf[g]],
        &S1 = shared.s1[shared.widthOf[g]], &S8 = shared.s8[shared.positionOf[g]];
  double gates[MauchCylinder::kMaxGates];
  std::size_t k = 0, r = 0;
  for (std::size_t f = 0; f < set.files.size(); ++f) {
    const BenchData& d = set.files[f];
    double s2 = 0.0;
    for (std::size_t i = 0; i < d.time.size(); ++i, ++r) {
      if (i > 0)
        for (int j = 0; j < kSubsteps; ++j, ++k) s2 = B[k] + (s2 - B[k]) * E[k];
      cylinder.calcGates(combineMauchSwitches(S1[r], s2, S8[r]), gates);
      const double x = d.position[i], xd = d.velocity[i];
      for (int q = 0; q < numGates; ++q) {
        Xg(static_cast<Eigen::Index>(r), 3 * q) = gates[q];
        Xg(static_cast<Eigen::Index>(r), 3 * q + 1) = gates[q] * x;
        Xg(static_cast<Eigen::Index>(r), 3 * q + 2) = gates[q] * xd;
      }
      if (p > 3 * numGates) {
        double row[3 * MauchCylinder::kMaxGates + 4];
        cylinder.calcRegressorRow(x, xd, set.accel[f][i], s2, row);
        for (int c = 3 * numGates; c < p; ++c) Xg(static_cast<Eigen::Index>(r), c) = row[c];
      }
    }
  }
}

// The costs of grid points first, first + step, ... into `costs`.
void evaluateGridCosts(const MauchCylinderParams& model, const TrainingSet& set,
                       const std::vector<MauchSwitchParams>& grid, const SharedSwitchValues& shared, std::size_t first,
                       std::size_t step, std::vector<double>& costs) {
  ProjectedResidual projected(model, set);
  MauchCylinderParams params = model;
  for (std::size_t g = first; g < grid.size(); g += step) {
    params.switches = grid[g];
    const MauchCylinder cylinder(params);
    Eigen::MatrixXd& Xg = projected.updRegressors(set.rows, cylinder.numCoefficients());
    buildGridRegressors(cylinder, set, shared, g, Xg);
    costs[g] = projected.projectRegressors().squaredNorm();
  }
}

}  // namespace

std::vector<double> calcGridCosts(const MauchCylinderParams& model, const TrainingSet& set,
                                  const std::vector<MauchSwitchParams>& grid, int threads) {
  SharedSwitchValues shared(set, grid);
  std::vector<double> costs(grid.size());
  auto evaluate = [&](std::size_t first, std::size_t step) {
    evaluateGridCosts(model, set, grid, shared, first, step, costs);
  };
  if (threads > 1) {
    // async | deferred: where a thread cannot start (a memory or process limit), the half
    // runs in this thread at get() instead of throwing std::system_error.
    auto other = std::async(kAsyncOrHere, [&] { shared.fill(1, 2); });
    shared.fill(0, 2);
    other.get();
    auto second = std::async(kAsyncOrHere, evaluate, 1, 2);
    evaluate(0, 2);
    second.get();
  } else {
    shared.fill(0, 1);
    evaluate(0, 1);
  }
  return costs;
}

std::vector<double> calcSwitchGridCosts(const MauchCylinderParams& model, const std::vector<BenchData>& train,
                                        const std::vector<MauchSwitchParams>& grid) {
  const TrainingSet set(model, train);
  return calcGridCosts(model, set, grid, 2);
}

}  // namespace swingsim
