#include "leg/thigh_motion.h"

#include <Simbody.h>

#include <cmath>
#include <string>

#include "core/input_error.h"

namespace swingsim {

struct ThighMotion::Impl {
  ThighKinematics kinematics;
  SimTK::Spline spline;
  double fitRms = 0;
};

namespace {

void check(const ThighKinematics& k) {
  const std::string where = k.path.empty() ? std::string("thigh kinematics") : k.path;
  const std::size_t n = k.time.size();
  if (k.hipFlexion.size() != n)
    throw InputError(where + ": expected one hip flexion per time (" + std::to_string(n) + "), found " +
                     std::to_string(k.hipFlexion.size()));
  if (n < static_cast<std::size_t>(ThighMotion::kMinSamples))
    throw InputError(where + ": expected at least " + std::to_string(ThighMotion::kMinSamples) +
                     " thigh angle samples to prescribe the thigh, found " + std::to_string(n));
  if (k.time[0] != 0)
    throw InputError(where + ": the first sample must be toe-off at time 0 s (found " + formatNumber(k.time[0]) +
                     " s)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(k.hipFlexion[i]) || !std::isfinite(k.time[i]))
      throw InputError(where + ": sample " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(k.time[i] > k.time[i - 1]))
      throw InputError(where + ": times must strictly increase (found " + formatNumber(k.time[i]) + " s after " +
                       formatNumber(k.time[i - 1]) + " s)");
  }
}

}  // namespace

ThighMotion::ThighMotion(const ThighKinematics& kinematics) {
  check(kinematics);
  const int n = static_cast<int>(kinematics.time.size());
  SimTK::Vector x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = kinematics.time[static_cast<std::size_t>(i)];
    y[i] = kinematics.hipFlexion[static_cast<std::size_t>(i)];
  }
  auto impl = std::make_shared<Impl>();
  impl->kinematics = kinematics;
  try {
    impl->spline = SimTK::SplineFitter<SimTK::Real>::fitFromGCV(5, x, y).getSpline();
  } catch (const std::exception& e) {  // SimTK's GCVSPL refuses what it cannot fit
    throw InputError((kinematics.path.empty() ? std::string("thigh kinematics") : kinematics.path) +
                     ": the thigh angle could not be fitted by a smoothing spline (" + e.what() + ")");
  }
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = impl->spline.calcValue(x[i]) - y[i];
    sum += r * r;
  }
  impl->fitRms = std::sqrt(sum / n);
  impl_ = std::move(impl);
}

double ThighMotion::calcAngle(double t) const { return impl_->spline.calcValue(t); }
double ThighMotion::calcRate(double t) const { return impl_->spline.calcDerivative(1, t); }
double ThighMotion::calcAcceleration(double t) const { return impl_->spline.calcDerivative(2, t); }
double ThighMotion::getEndTime() const { return impl_->kinematics.time.back(); }
double ThighMotion::getFitRms() const { return impl_->fitRms; }
const ThighKinematics& ThighMotion::getKinematics() const { return impl_->kinematics; }

}  // namespace swingsim
