#pragma once
// Measurement noise of a sampled signal, estimated from the signal alone: the difference-
// based estimator of Gasser, Sroka & Jennen-Steinmetz (1986, Biometrika 73:625). Each
// pseudo-residual is the sample minus the straight line through its two neighbours,
// scaled so that its variance equals the noise variance for white noise on a smooth
// signal; the noise standard deviation is a robust scale (1.4826 x median absolute
// pseudo-residual), so the few samples where the signal itself bends sharply (a valve
// switch, the knee reaching its stop) do not inflate it. Needs a signal that is smooth on
// the scale of the sampling interval: its second difference small beside the noise (at the
// bench's 361 Hz and a 1 s stride, about 4 N against tens of N of load-cell noise).
#include <vector>

namespace swingsim {

struct NoiseEstimate {
  double sigma = 0;         ///< estimated noise standard deviation, unit of the signal
  std::size_t samples = 0;  ///< pseudo-residuals used
};

/// Noise of `values` sampled at strictly increasing `time` (uneven spacing allowed). Throws
/// std::invalid_argument for fewer than 3 samples or mismatched lengths.
NoiseEstimate estimateNoise(const std::vector<double>& time, const std::vector<double>& values);

/// Pooled over several records: the root mean square of their sigmas weighted by samples.
NoiseEstimate poolNoise(const std::vector<NoiseEstimate>& estimates);

}  // namespace swingsim
