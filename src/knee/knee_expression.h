#pragma once
// A knee moment a user writes as an expression (muparser, Debian's libmuparser-dev) in the
// knee's and the hip's state and the time since toe-off: the effect a diagnosis finds missing
// and no library effect stands for (docs/diagnosis.md, "Your own effect"). The result is a
// knee moment in N m, positive in flexion (KneeLaw's convention), so a moment resisting
// extension is positive while the knee extends. In the spirit of OpenSim's
// ExpressionBasedCoordinateForce (an expression in q and qdot inside the model file).
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "knee/knee_law.h"

namespace swingsim {

/// One named parameter of an expression: its value in the user's unit (the expression is
/// written in that unit; swingsim does not convert it).
struct KneeExpressionParameter {
  std::string name;  ///< an identifier the expression uses: "c"
  std::string unit;  ///< a label for reports: "N m s/rad"
  double value = 0;
};

/// A user's knee moment: a name, the expression and its parameters.
struct KneeExpressionParams {
  std::string name;        ///< the effect's name: "my_cushion"
  std::string expression;  ///< the knee moment, N m, + = flexion
  std::vector<KneeExpressionParameter> parameters;
};

/// The state variables an expression may use, each with its unit and meaning, in the order
/// a user is told them.
struct KneeExpressionVariable {
  const char* name;
  const char* meaning;
};
const std::vector<KneeExpressionVariable>& kneeExpressionVariables();

/// A parse error: the parser's message and the 0-based character position in the
/// expression (-1: not tied to a position).
class KneeExpressionError : public std::invalid_argument {
 public:
  KneeExpressionError(const std::string& message, int position)
      : std::invalid_argument(message), position_(position) {}
  int position() const { return position_; }

 private:
  int position_;
};

/// One line for a user: the parser's message and where in `expression` it stopped
/// ("Unexpected token "x" found at position 12. (character 13: "x * 2")").
std::string describeKneeExpressionError(const std::string& expression, const KneeExpressionError& error);

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
  struct Parser;  ///< the parser bound to its variables (knee_expression.cpp)

 private:
  KneeExpressionParams p_;
  std::unique_ptr<Parser> parser_;
  mutable std::mutex mutex_;
};

}  // namespace swingsim
