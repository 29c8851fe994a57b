#pragma once
// A user's expression (muparser, Debian's libmuparser-dev) over named state variables and
// fitted parameters, shared by the two places a user writes one: a knee moment
// (knee/knee_expression.h) and a cylinder force (knee/cylinder_expression.h). Each says
// which state variables its expressions may use; this unit parses, checks and evaluates.
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace swingsim {

/// One named parameter of an expression: its value in the user's unit (the expression is
/// written in that unit; swingsim does not convert it).
struct KneeExpressionParameter {
  std::string name;  ///< an identifier the expression uses: "c"
  std::string unit;  ///< a label for reports: "N m s/rad"
  double value = 0;
};

/// A user's expression: a name, the text and its parameters. What it computes (a knee moment
/// in N m, a cylinder force in N) is said by where it sits.
struct KneeExpressionParams {
  std::string name;        ///< the effect's name: "my_cushion"
  std::string expression;  ///< "-c * knee_rate_rad_s * (knee_deg < 15 ? 1 : 0)"
  std::vector<KneeExpressionParameter> parameters;
};

/// A state variable an expression may use, with its unit and meaning.
struct KneeExpressionVariable {
  const char* name;
  const char* meaning;
};

/// A parse error: the parser's message and the 0-based character position in the
/// expression (-1: not tied to a position).
class KneeExpressionError : public std::invalid_argument {
 public:
  KneeExpressionError(const std::string& message, int position) : std::invalid_argument(message), position_(position) {}
  int position() const { return position_; }

 private:
  int position_;
};

/// One line for a user: the parser's message and where in `expression` it stopped
/// ("Unexpected token "x" found at position 12. (character 13: "x * 2")").
std::string describeKneeExpressionError(const std::string& expression, const KneeExpressionError& error);

/// Throws KneeExpressionError if the expression does not parse, uses a name that is neither
/// one of `variables` nor one of its parameters, if a parameter's name is not an identifier
/// or is a variable's, if two parameters share a name, or if a parameter is not used.
/// `quantity` says what the expression computes, for the empty-text message
/// ("the knee moment in N m (+ = flexion)").
void checkExpression(const KneeExpressionParams& params, const std::vector<KneeExpressionVariable>& variables,
                     const std::string& quantity);

/// An expression bound to its variables: set state()[i] (in `variables`' order), then eval().
/// Not for use by two threads at once.
class ExpressionParser {
 public:
  /// Throws KneeExpressionError as checkExpression (without its checks of the names).
  ExpressionParser(const KneeExpressionParams& params, const std::vector<KneeExpressionVariable>& variables);
  ~ExpressionParser();
  ExpressionParser(const ExpressionParser&) = delete;
  ExpressionParser& operator=(const ExpressionParser&) = delete;
  double* state();
  double eval();
  /// The variables and parameters the expression uses.
  std::set<std::string> usedNames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace swingsim
