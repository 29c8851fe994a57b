#pragma once
// A knee moment a user writes as an expression (muparser, Debian's libmuparser-dev) in the
// knee's and the hip's state and the time since toe-off: the effect a diagnosis finds missing
// and no library effect stands for (docs/diagnosis.md, "Your own effect: a knee moment you write"). The result is a
// knee moment in N m, positive in flexion (KneeLaw's convention), so a moment resisting
// extension is positive while the knee extends. In the spirit of OpenSim's
// ExpressionBasedCoordinateForce (an expression in q and qdot inside the model file).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "knee/expression_parser.h"
#include "knee/knee_law.h"

namespace swingsim {

/// The state variables a knee moment's expression may use, each with its unit and meaning,
/// in the order a user is told them.
const std::vector<KneeExpressionVariable>& kneeExpressionVariables();

/// Throws KneeExpressionError if the expression does not parse, uses a name that is neither
/// a state variable nor one of its parameters, if a parameter's name is not an identifier or
/// is a state variable's, or if two parameters share a name.
void checkKneeExpression(const KneeExpressionParams& params);

/// The expression as a knee law. Not passive (nothing is known of the expression's sign), so
/// a swing under it never stops early on energy (KneeLaw::isPassive). One object evaluates
/// under a lock: copies (clone()) are what run in parallel. calcMoment throws
/// std::domain_error when the expression is not finite at a state.
class KneeExpressionMoment final : public KneeLaw {
 public:
  explicit KneeExpressionMoment(KneeExpressionParams params);
  ~KneeExpressionMoment() override;
  const KneeExpressionParams& params() const { return p_; }
  std::string name() const override { return p_.name; }
  double calcMoment(const KneeKinematics& knee, const double* z) const override;
  std::unique_ptr<KneeLaw> clone() const override { return std::make_unique<KneeExpressionMoment>(p_); }

 private:
  KneeExpressionParams p_;
  std::unique_ptr<ExpressionParser> parser_;
  mutable std::mutex mutex_;
};

}  // namespace swingsim
