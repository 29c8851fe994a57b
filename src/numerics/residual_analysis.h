#pragma once
// Residual analysis for `swingsim compare` and `swingsim diagnose`: where and when a model
// fails. Residual = measured - predicted. Residuals of a smooth model misfit sampled at
// hundreds of Hz are strongly autocorrelated, so every count of "independent" samples here
// is an effective sample size, not the number of rows.
#include <string>
#include <vector>

namespace swingsim {

/// Residual series of several records kept apart (autocorrelation never spans two files).
using ResidualSegments = std::vector<std::vector<double>>;

/// Autocorrelation at lags 0..maxLag pooled over segments (lag pairs within one segment,
/// overall mean removed, normalised by the lag-0 sum). Throws std::invalid_argument if
/// maxLag < 0 or there is no sample.
std::vector<double> calcAutocorrelation(const ResidualSegments& residuals, int maxLag);

/// Effective number of independent samples under an AR(1) reading of the residual:
/// n (1 - rho1) / (1 + rho1), rho1 the pooled lag-1 autocorrelation clamped to [0, 0.999].
/// Equals n for white residuals; about 1/(1 - rho1)/2 times fewer for a smooth misfit.
double calcEffectiveSampleSize(const ResidualSegments& residuals);

/// Ljung-Box portmanteau test of whiteness over lags 1..lags: Q = n (n + 2) sum rho_k^2 /
/// (n - k) and its p-value under chi^2(lags).
///
/// The lags scale with the record: at most a fifth of the shortest segment
/// (kWhitenessLagDivisor), so every record contributes pairs at every lag and the sum stays
/// a chi^2 (Ljung & Box 1978 assume lags well below n; more lags than samples give Q < 0 or
/// NaN). A short swing keeps a test with fewer lags. A test that cannot be computed (fewer
/// than kMinWhitenessLags usable lags, a non-finite or constant residual, a non-finite Q or
/// p) has `computed` false and says why in `note`: it is "cannot tell", never a pass.
struct WhitenessTest {
  double q = 0;
  double pValue = 1;
  int lags = 0;             ///< lags used (<= requestedLags)
  int requestedLags = 0;    ///< lags the study asked for
  int lagsOutsideBand = 0;  ///< lags with |rho| above the 99 % band 2.576 / sqrt(n)
  bool computed = false;    ///< q and pValue are finite and mean something
  std::string note;         ///< why it was not computed, or that the lags were reduced
};
/// The lags a record of segments supports: at most shortest segment / kWhitenessLagDivisor.
constexpr int kWhitenessLagDivisor = 5;
/// Fewest usable lags for a whiteness test (a record of under 10 samples has none).
constexpr int kMinWhitenessLags = 2;
/// min(requested, shortest non-empty segment / kWhitenessLagDivisor); 0 with no sample.
int calcWhitenessLags(const ResidualSegments& residuals, int requested);
WhitenessTest calcWhitenessTest(const ResidualSegments& residuals, int lags);

/// White, not white, or cannot tell (a test that was not computed).
enum class Whiteness { kWhite, kNotWhite, kCannotTell };
/// The test's outcome at level `alpha`: kWhite only for a computed test with p >= alpha.
Whiteness judgeWhiteness(const WhitenessTest& test, double alpha);

/// Upper tail probability of chi^2 with `dof` degrees of freedom at `x` (1 for x <= 0; NaN
/// for a NaN x or dof <= 0, so that a statistic that could not be computed never passes).
double calcChiSquaredSurvival(double x, double dof);
/// The `p` quantile of the standard normal distribution (0 < p < 1).
double calcNormalQuantile(double p);
/// The `p` quantile of chi^2 with `dof` degrees of freedom (0 < p < 1).
double calcChiSquaredQuantile(double p, double dof);

/// Fewest samples in a bin of the binned mean residual. Its band comes from the within-bin
/// spread s, estimated with count - 1 degrees of freedom: s^2 / sigma^2 ~ chi^2(m - 1) / (m - 1).
/// With 2 samples s < sigma / 10 has probability 8 % (the band collapses and a bin reads as
/// "hundreds of half-widths" off zero); with 5 samples it has 2e-4. A 60 Hz swing of ~25
/// samples in 12 bins would give 2-samples bins.
constexpr std::size_t kMinBinSamples = 5;

/// Power of the chi^2(dof) test at level `alpha` (reject when the statistic exceeds the
/// 1 - alpha quantile) when the statistic is noncentral chi^2(dof, lambda): the likelihood
/// ratio of a true effect of noncentrality lambda (Boost.Math non_central_chi_squared).
double calcChiSquaredPower(double lambda, double dof, double alpha);

/// The smallest number of records N >= 1 for which a noncentrality of N * lambdaPerRecord
/// (the likelihood ratio grows with the number of independent records) reaches `power` at
/// level `alpha`; 0 if lambdaPerRecord <= 0 or more than maxRecords would be needed.
int calcRecordsForPower(double lambdaPerRecord, double dof, double alpha, double power, int maxRecords = 100000);

/// Mean residual in equal-count bins of a variable, with a 99 % confidence half-width that
/// uses the effective sample size (the within-bin spread / sqrt(count * nEff / n)). Fewer
/// bins than asked when the samples are few: every bin holds at least kMinBinSamples (the
/// short bins merged into their neighbours); no bins if n < kMinBinSamples. Equal variable
/// values keep their sample order (the bins do not depend on the sort's whims). A bin whose
/// spread is zero has no band (halfWidth 0) and takes no part in the search for maxBin.
/// Ties in significance go to the lowest bin.
struct BinnedResidual {
  std::vector<double> center;        ///< mean of the variable in the bin
  std::vector<double> lower, upper;  ///< smallest and largest value of the variable in the bin
  std::vector<double> mean;          ///< mean residual
  std::vector<double> halfWidth;     ///< 99 % confidence half-width
  /// Largest |mean| / halfWidth over the bins (> 1: that bin's mean is not zero at 99 %).
  double maxSignificance = 0;
  std::size_t maxBin = 0;
  /// The contiguous run of bins around maxBin whose means are nonzero at 99 % with maxBin's
  /// sign (runFirst..runLast, bin indices; both maxBin if maxSignificance <= 1): where in the
  /// variable's range the residual sits.
  std::size_t runFirst = 0, runLast = 0;
};
BinnedResidual calcBinnedResidual(const std::vector<double>& variable, const std::vector<double>& residual, int bins,
                                  double nEffOverN);

}  // namespace swingsim
