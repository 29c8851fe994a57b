#pragma once
// What the embedded Runge-Kutta pairs (dormand_prince.h, bogacki_shampine.h) share: the
// check of their tolerances and the error norm their step-size control compares with 1.
#include <vector>

namespace swingsim {

/// Throws std::invalid_argument("<method>: tolerances must be positive and finite") unless
/// relTol and absTol are both positive and finite.
void checkStepTolerances(const char* method, double relTol, double absTol);

/// Hairer I, Eq. II.4.11: sqrt(mean_i (err_i / (absTol + relTol max(|y0_i|, |y1_i|)))^2),
/// over the n = err.size() components of the step-start state y0, the step-end state y1 and
/// the embedded error estimate err.
double calcStepErrorNorm(const std::vector<double>& y0, const std::vector<double>& y1, const std::vector<double>& err,
                         double relTol, double absTol);

}  // namespace swingsim
