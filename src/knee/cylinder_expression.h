#pragma once
// A cylinder force a user writes as an expression (knee/expression_parser.h) in the piston's
// position and speed: the effect a cylinder diagnosis finds missing and no library effect
// stands for (docs/diagnosis.md, "Your own effect: a cylinder force you write"). The result is a force in N added to
// the Mauch cylinder's (knee/mauch_cylinder.h), in its convention: positive resists compression (x > 0 in flexion, so a
// force resisting flexion is positive while the piston compresses).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "knee/expression_parser.h"

namespace swingsim {

/// The state variables a cylinder force's expression may use.
const std::vector<KneeExpressionVariable>& cylinderExpressionVariables();

/// Throws KneeExpressionError as checkExpression, for a cylinder force.
void checkCylinderExpression(const KneeExpressionParams& params);

/// The users' cylinder forces of one model, summed. Each copy has its own parsers, so copies
/// run in parallel; one object evaluates under a lock.
class CylinderExpressionForces {
 public:
  CylinderExpressionForces() = default;
  /// Throws KneeExpressionError if an expression does not check.
  explicit CylinderExpressionForces(std::vector<KneeExpressionParams> expressions);
  CylinderExpressionForces(const CylinderExpressionForces& other) : CylinderExpressionForces(other.params_) {}
  CylinderExpressionForces& operator=(const CylinderExpressionForces& other);
  ~CylinderExpressionForces();
  bool empty() const { return params_.empty(); }
  /// The summed force (N) at piston position x (m) and speed xd (m/s). Throws
  /// std::domain_error, naming the expression and the state, where it is not finite.
  double calcForce(double x, double xd) const;

 private:
  std::vector<KneeExpressionParams> params_;
  std::vector<std::unique_ptr<ExpressionParser>> parsers_;
  mutable std::mutex mutex_;
};

}  // namespace swingsim
