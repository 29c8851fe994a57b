#pragma once
// Derivative of a sampled signal.
#include <vector>

namespace swingsim {

/// Derivative of x(t) from samples: second-order central differences on the (possibly
/// uneven) time grid, one-sided at both ends. The bench generator and the cylinder fit use
/// the same estimate of the piston velocity, so a model fitted to generated data sees
/// exactly the velocity that made the force.
std::vector<double> estimatePistonVelocity(const std::vector<double>& time, const std::vector<double>& x);

}  // namespace swingsim
