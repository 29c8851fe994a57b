#include "leg/hip_path.h"

#include <Simbody.h>

#include <cmath>
#include <vector>

#include "core/input_error.h"

namespace swingsim {

struct HipPath::Impl {
  std::vector<double> x, y;  // the hip centre's samples, m
  SimTK::Spline splineX, splineY;
  double fitRms = 0;
  double first = 0, last = 0;  // s: the first and last sample times
};

namespace {

void checkColumn(const std::string& where, const char* name, const std::vector<double>& column, std::size_t n) {
  if (column.size() != n)
    throw InputError(where + ": " + name + ": expected one value per time (" + std::to_string(n) + ") (got " +
                     std::to_string(column.size()) + ")");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(column[i]))
      throw InputError(where + ": " + name + ": expected a finite value at sample " + std::to_string(i + 1) + " (got " +
                       formatNumber(column[i]) + ")");
}

SimTK::Spline fit(const std::string& where, const std::vector<double>& time, const std::vector<double>& value) {
  const int n = static_cast<int>(time.size());
  SimTK::Vector t(n), v(n);
  for (int i = 0; i < n; ++i) {
    t[i] = time[static_cast<std::size_t>(i)];
    v[i] = value[static_cast<std::size_t>(i)];
  }
  try {
    return SimTK::SplineFitter<SimTK::Real>::fitFromGCV(5, t, v).getSpline();
  } catch (const std::exception& e) {  // SimTK's GCVSPL refuses what it cannot fit
    throw InputError(where + ": the hip joint centre's path could not be fitted by a smoothing spline (" + e.what() +
                     ")");
  }
}

// The spline's derivative of `order` at t. SimTK's spline refuses a t outside the samples;
// there (an integrator's stage may land a rounding error past the last sample) the end's
// polynomial piece is continued exactly by its Taylor series (a quintic: derivatives to 5).
double evaluate(const SimTK::Spline& spline, double first, double last, int order, double t) {
  if (t >= first && t <= last) return order == 0 ? spline.calcValue(t) : spline.calcDerivative(order, t);
  const double end = t < first ? first : last, h = t - end;
  double sum = 0, term = 1;
  for (int k = 0; order + k <= 5; ++k) {
    const int d = order + k;
    sum += (d == 0 ? spline.calcValue(end) : spline.calcDerivative(d, end)) * term;
    term *= h / (k + 1);
  }
  return sum;
}

}  // namespace

bool HipPath::hasPelvis(const ThighKinematics& k) {
  // The pelvis's translation moves the hip; its tilt alone only turns the thigh's angle in
  // space (already in hipFlexion), with the hip left where Burkett fixed it.
  return !k.pelvisX.empty() || !k.pelvisY.empty();
}

HipPath::HipPath(const ThighKinematics& k, const std::optional<std::array<double, 2>>& offset,
                 const std::string& participantPath) {
  const std::string where = k.path.empty() ? std::string("thigh kinematics") : k.path;
  if (!offset)
    throw InputError((participantPath.empty() ? std::string("participant") : participantPath) +
                     ": hip_offset_in_pelvis_m: expected the hip joint centre in the pelvis frame [x, y] m, since " +
                     where + " has the pelvis (got no key; swingsim import-osim writes it from the model)");
  const std::size_t n = k.time.size();
  checkColumn(where, "pelvis_tx", k.pelvisX, n);
  checkColumn(where, "pelvis_ty", k.pelvisY, n);
  checkColumn(where, "pelvis_tilt", k.pelvisTilt, n);
  if (n < 6)  // GCVSPL needs at least 2 x 3 samples for degree 5 (as ThighMotion)
    throw InputError(where + ": expected at least 6 pelvis samples to move the hip (got " + std::to_string(n) + ")");

  auto impl = std::make_shared<Impl>();
  const double ox = (*offset)[0], oy = (*offset)[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double c = std::cos(k.pelvisTilt[i]), s = std::sin(k.pelvisTilt[i]);
    impl->x.push_back(k.pelvisX[i] + c * ox - s * oy);
    impl->y.push_back(k.pelvisY[i] + s * ox + c * oy);
  }
  impl->splineX = fit(where, k.time, impl->x);
  impl->splineY = fit(where, k.time, impl->y);
  impl->first = k.time.front();
  impl->last = k.time.back();
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = impl->splineX.calcValue(k.time[i]) - impl->x[i];
    const double dy = impl->splineY.calcValue(k.time[i]) - impl->y[i];
    sum += dx * dx + dy * dy;
  }
  impl->fitRms = std::sqrt(sum / static_cast<double>(n));
  impl_ = std::move(impl);
}

std::array<double, 2> HipPath::calcDerivative(int order, double t) const {
  const Impl& i = *impl_;
  return {evaluate(i.splineX, i.first, i.last, order, t), evaluate(i.splineY, i.first, i.last, order, t)};
}
std::array<double, 2> HipPath::calcPosition(double t) const { return calcDerivative(0, t); }
std::array<double, 2> HipPath::calcVelocity(double t) const { return calcDerivative(1, t); }
std::array<double, 2> HipPath::calcAcceleration(double t) const { return calcDerivative(2, t); }
std::array<double, 2> HipPath::getSample(std::size_t i) const { return {impl_->x.at(i), impl_->y.at(i)}; }
double HipPath::getFitRms() const { return impl_->fitRms; }

}  // namespace swingsim
