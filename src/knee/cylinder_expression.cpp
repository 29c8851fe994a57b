#include "knee/cylinder_expression.h"

#include <cmath>
#include <stdexcept>

#include "core/input_error.h"

namespace swingsim {

const std::vector<KneeExpressionVariable>& cylinderExpressionVariables() {
  static const std::vector<KneeExpressionVariable> v = {
      {"position_m", "piston position, m (+ compressed, in flexion; 0 at full extension)"},
      {"position_mm", "piston position, mm"},
      {"speed_m_s", "piston speed, m/s (+ compressing, in flexion; - extending)"},
      {"speed_mm_s", "piston speed, mm/s"},
  };
  return v;
}

void checkCylinderExpression(const KneeExpressionParams& p) {
  checkExpression(p, cylinderExpressionVariables(), "the cylinder force in N (+ resists compression)");
}

CylinderExpressionForces::CylinderExpressionForces(std::vector<KneeExpressionParams> expressions)
    : params_(std::move(expressions)) {
  for (const auto& x : params_) {
    checkCylinderExpression(x);
    parsers_.push_back(std::make_unique<ExpressionParser>(x, cylinderExpressionVariables()));
  }
}

CylinderExpressionForces& CylinderExpressionForces::operator=(const CylinderExpressionForces& other) {
  if (this == &other) return *this;
  CylinderExpressionForces copy(other.params_);
  std::lock_guard<std::mutex> lock(mutex_);
  params_ = std::move(copy.params_);
  parsers_ = std::move(copy.parsers_);
  return *this;
}

CylinderExpressionForces::~CylinderExpressionForces() = default;

double CylinderExpressionForces::calcForce(double x, double xd) const {
  double total = 0;
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t i = 0; i < parsers_.size(); ++i) {
    double* s = parsers_[i]->state();  // in cylinderExpressionVariables()'s order
    s[0] = x;
    s[1] = x * 1e3;
    s[2] = xd;
    s[3] = xd * 1e3;
    const double f = parsers_[i]->eval();
    if (!std::isfinite(f))
      throw std::domain_error(params_[i].name + ": the expression is not finite (" + formatNumber(f) + ") at piston " +
                              formatNumber(x * 1e3) + " mm, " + formatNumber(xd * 1e3) + " mm/s");
    total += f;
  }
  return total;
}

}  // namespace swingsim
