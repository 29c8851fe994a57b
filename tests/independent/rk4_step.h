#pragma once
// One classical Runge-Kutta 4 step of a one-degree-of-freedom motion q'' = acc(q, q'), for
// the tests that integrate a law in time themselves with a small fixed step (no code shared
// with src/'s integrators).
namespace swingsim::testing {

template <class Acceleration>
void stepRk4(double& q, double& u, double h, const Acceleration& acc) {
  const double k1q = u, k1u = acc(q, u);
  const double k2q = u + 0.5 * h * k1u, k2u = acc(q + 0.5 * h * k1q, u + 0.5 * h * k1u);
  const double k3q = u + 0.5 * h * k2u, k3u = acc(q + 0.5 * h * k2q, u + 0.5 * h * k2u);
  const double k4q = u + h * k3u, k4u = acc(q + h * k3q, u + h * k3u);
  q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
  u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
}

}  // namespace swingsim::testing
