#pragma once
// Monotone piecewise-cubic interpolation of sampled data (Fritsch & Carlson 1980, "Monotone
// piecewise cubic interpolation", SIAM J. Numer. Anal. 17:238-246): C1, and no overshoot
// between samples, so a measured moment table never dips or peaks where the data do not.
// Used by the dynamometer damping table and the tabulated hip moment.
#include <vector>

namespace swingsim {

/// Slopes at the first and last sample.
enum class MonotoneCubicEnds {
  kSecant,  ///< the one-sided secant (the curve enters the held end value with a kink)
  kFlat,    ///< zero: C1 into the constant held beyond the ends
};

/// y(t) through (x[i], y[i]) (x strictly increasing, at least 2 samples), held at y.front()
/// and y.back() outside [x.front(), x.back()]. Interior slopes are the weighted harmonic mean
/// of the neighbouring secants (Fritsch & Butland 1984, "A method for constructing local
/// monotone piecewise cubic interpolants", SIAM J. Sci. Stat. Comput. 5:300-304; the slopes
/// of PCHIP), zero where the data turn: they satisfy Fritsch & Carlson's monotonicity
/// conditions, so the curve is monotone wherever the data are.
double interpolateMonotoneCubic(const std::vector<double>& x, const std::vector<double>& y, double t,
                                MonotoneCubicEnds ends);

}  // namespace swingsim
