#include "knee/knee_expression.h"

#include <cmath>

#include "core/units.h"

namespace swingsim {

const std::vector<KneeExpressionVariable>& kneeExpressionVariables() {
  static const std::vector<KneeExpressionVariable> v = {
      {"knee_deg", "knee flexion, deg (+ flexion, - hyperextension)"},
      {"knee_rad", "knee flexion, rad"},
      {"knee_rate_deg_s", "knee flexion rate, deg/s (+ flexing, - extending)"},
      {"knee_rate_rad_s", "knee flexion rate, rad/s"},
      {"hip_deg", "hip flexion (thigh from hanging straight down, forward +), deg"},
      {"hip_rad", "hip flexion, rad"},
      {"hip_rate_deg_s", "hip flexion rate, deg/s"},
      {"hip_rate_rad_s", "hip flexion rate, rad/s"},
      {"time_s", "time since toe-off, s"},
  };
  return v;
}

void checkKneeExpression(const KneeExpressionParams& p) {
  checkExpression(p, kneeExpressionVariables(), "the knee moment in N m (+ = flexion)");
}

KneeExpressionMoment::KneeExpressionMoment(KneeExpressionParams params) : p_(std::move(params)) {
  checkKneeExpression(p_);
  parser_ = std::make_unique<ExpressionParser>(p_, kneeExpressionVariables());
}

KneeExpressionMoment::~KneeExpressionMoment() = default;

double KneeExpressionMoment::calcMoment(const KneeKinematics& knee, const double* /*z*/) const {
  double m;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    double* x = parser_->state();  // in kneeExpressionVariables()'s order
    x[0] = knee.flexion * kRadToDeg;
    x[1] = knee.flexion;
    x[2] = knee.flexionRate * kRadToDeg;
    x[3] = knee.flexionRate;
    x[4] = knee.hipFlexion * kRadToDeg;
    x[5] = knee.hipFlexion;
    x[6] = knee.hipFlexionRate * kRadToDeg;
    x[7] = knee.hipFlexionRate;
    x[8] = knee.time;
    m = parser_->eval();
  }
  if (!std::isfinite(m))
    throw std::domain_error(p_.name + ": the expression is not finite (" + std::to_string(m) + ") at knee " +
                            std::to_string(knee.flexion * kRadToDeg) + " deg, " +
                            std::to_string(knee.flexionRate * kRadToDeg) + " deg/s");
  return m;
}

}  // namespace swingsim
