#include "identify/sweep_rows.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/input_error.h"
#include "model/leg_parameters.h"
#include "sweep/sweep_uncertainty.h"

namespace swingsim {

namespace {

constexpr double kMillimetresPerMetre = 1000.0;

}  // namespace

std::vector<SweepParticipantRows> assignSweepRows(const SweepStudy& study, const std::vector<MeasuredSwingTime>& rows,
                                                  const std::string& measuredPath, double defaultStandardError,
                                                  std::vector<bool>& hasStandard, std::vector<std::string>& notes) {
  std::vector<SweepParticipantRows> participants;
  std::map<std::string, std::size_t> index;
  for (const auto& p : study.participants) {
    index[p.name] = participants.size();
    SweepParticipantRows r;
    r.nominal = makeNominalVariant(study, p);
    r.standard.line = 0;
    participants.push_back(r);
  }
  hasStandard.assign(participants.size(), false);
  for (const auto& row : rows) {
    const auto it = index.find(row.participant);
    if (it == index.end()) {
      std::string known;
      for (const auto& p : study.participants) known += (known.empty() ? "" : ", ") + p.name;
      throw InputError(measuredPath + ":" + std::to_string(row.line) +
                       ": participant: expected the name of a participant "
                       "of the sweep study " +
                       study.path + " (" + known + ") (got '" + row.participant + "')");
    }
    double se = std::isnan(row.sd) ? defaultStandardError : row.calcStandardError();
    if (!(se > 0))
      throw InputError(measuredPath + ":" + std::to_string(row.line) +
                       ": sd_s: expected the trial-to-trial SD and n of "
                       "every row (columns sd_s,n), or acceptance: measurement_noise (ms, the standard error of a row) "
                       "in the study (got neither)");
    SweepParticipantRows& p = participants[it->second];
    if (row.lowering == 0) {
      p.standard = row;
      p.standardRowError = se;
      hasStandard[it->second] = true;
      continue;
    }
    const double cap = calcMaxLowering(p.nominal.participant);
    if (row.lowering > cap) {
      notes.push_back(measuredPath + ":" + std::to_string(row.line) + ": " + row.participant + " at " +
                      formatNumber(row.lowering * kMillimetresPerMetre) +
                      " mm is beyond the shank's physical limit of " + formatNumber(cap * kMillimetresPerMetre) +
                      " mm (model/leg_parameters.h calcMaxLowering); row left out");
      continue;
    }
    p.lowered.push_back(row);
    p.standardErrors.push_back(se);
  }
  return participants;
}

void whitenSweepRows(SweepParticipantRows& p, bool hasStandard) {
  // Lowered rows in order of lowering (their standard errors with them).
  std::vector<std::size_t> order(p.lowered.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return p.lowered[a].lowering < p.lowered[b].lowering; });
  std::vector<MeasuredSwingTime> lowered;
  std::vector<double> errors;
  for (std::size_t k : order) {
    lowered.push_back(p.lowered[k]);
    errors.push_back(p.standardErrors[k]);
  }
  p.lowered = lowered;
  // A held-out row's error carries its own noise and the standard row's, which its time
  // scale was calibrated to (swing time ~ proportional to the scale): se^2 + (T_d/T_0)^2 se_0^2.
  // The shared part makes a participant's rows correlated: the likelihood uses them
  // whitened by the Cholesky factor of C = diag(se^2) + v v', v_k = (T_k/T_0) se_0
  // (generalized least squares), so a participant's rows count as independent samples.
  const auto n = static_cast<Eigen::Index>(errors.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd shared(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto row = static_cast<std::size_t>(k);
    shared[k] = hasStandard ? p.lowered[row].swingTime / p.standard.swingTime * p.standardRowError : 0.0;
    cov(k, k) = errors[row] * errors[row];
  }
  cov += shared * shared.transpose();
  p.whitening = n > 0 ? Eigen::MatrixXd(cov.llt().matrixL().solve(Eigen::MatrixXd::Identity(n, n))) : Eigen::MatrixXd();
  for (Eigen::Index k = 0; k < n; ++k) errors[static_cast<std::size_t>(k)] = std::sqrt(cov(k, k));
  // How many independent samples the rows' RMS is worth (Satterthwaite: (tr C)^2 / tr C^2).
  p.effectiveRows = n > 0 ? cov.trace() * cov.trace() / (cov * cov).trace() : 0.0;
  p.standardErrors = errors;
}

}  // namespace swingsim
