#include "knee/knee_expression.h"

#include <muParser.h>

#include <cmath>
#include <set>

#include "core/identifier.h"
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

// The parser, bound to its own variables: muparser reads them through pointers.
struct KneeExpressionMoment::Parser {
  mu::Parser parser;
  double state[9] = {};  // in kneeExpressionVariables()'s order
  std::vector<double> parameters;

  explicit Parser(const KneeExpressionParams& p) : parameters(p.parameters.size()) {
    const auto& vars = kneeExpressionVariables();
    for (std::size_t i = 0; i < vars.size(); ++i) parser.DefineVar(vars[i].name, &state[i]);
    for (std::size_t i = 0; i < p.parameters.size(); ++i) {
      parameters[i] = p.parameters[i].value;
      parser.DefineVar(p.parameters[i].name, &parameters[i]);
    }
    parser.SetExpr(p.expression);
    parser.Eval();  // muparser parses on the first evaluation: its errors come here
  }

  void set(const KneeKinematics& k) {
    state[0] = k.flexion * kRadToDeg;
    state[1] = k.flexion;
    state[2] = k.flexionRate * kRadToDeg;
    state[3] = k.flexionRate;
    state[4] = k.hipFlexion * kRadToDeg;
    state[5] = k.hipFlexion;
    state[6] = k.hipFlexionRate * kRadToDeg;
    state[7] = k.hipFlexionRate;
    state[8] = k.time;
  }
};

namespace {

std::string variableList() {
  std::string out;
  for (const auto& v : kneeExpressionVariables()) out += (out.empty() ? "" : ", ") + std::string(v.name);
  return out;
}

void checkParameterNames(const KneeExpressionParams& p) {
  std::set<std::string> seen;
  for (const auto& q : p.parameters) {
    if (!isIdentifier(q.name))
      throw KneeExpressionError("parameter '" + q.name + "': expected a name of letters, digits and _, not starting with a digit", -1);
    for (const auto& v : kneeExpressionVariables())
      if (q.name == v.name)
        throw KneeExpressionError("parameter '" + q.name + "': the name of a state variable (" + variableList() + ")", -1);
    if (!seen.insert(q.name).second) throw KneeExpressionError("parameter '" + q.name + "' is named twice", -1);
    if (!std::isfinite(q.value)) throw KneeExpressionError("parameter '" + q.name + "': expected a finite value", -1);
  }
}

}  // namespace

std::string describeKneeExpressionError(const std::string& expression, const KneeExpressionError& error) {
  std::string out = error.what();
  const int at = error.position();
  if (at >= 0 && static_cast<std::size_t>(at) <= expression.size())
    out += " (character " + std::to_string(at + 1) + " of the expression: \"" + expression.substr(static_cast<std::size_t>(at)) + "\")";
  return out;
}

void checkKneeExpression(const KneeExpressionParams& p) {
  checkParameterNames(p);
  if (p.expression.find_first_not_of(" \t\r\n") == std::string::npos)
    throw KneeExpressionError("expected an expression of the knee moment in N m (+ = flexion), found an empty text", -1);
  try {
    KneeExpressionMoment::Parser parser(p);
    const auto used = parser.parser.GetUsedVar();
    for (const auto& q : p.parameters)
      if (used.find(q.name) == used.end())
        throw KneeExpressionError("parameter '" + q.name + "' is not used by the expression: it could not be fitted", -1);
  } catch (const mu::Parser::exception_type& e) {
    std::string message = e.GetMsg();
    if (message.find("Unexpected token") != std::string::npos && !e.GetToken().empty())
      message += " (a name must be a state variable: " + variableList() + "; or one of the parameters)";
    throw KneeExpressionError(message, e.GetPos());
  }
}

KneeExpressionMoment::KneeExpressionMoment(KneeExpressionParams params) : p_(std::move(params)) {
  checkKneeExpression(p_);
  parser_ = std::make_unique<Parser>(p_);
}

KneeExpressionMoment::~KneeExpressionMoment() = default;

double KneeExpressionMoment::calcMoment(const KneeKinematics& knee, const double* /*z*/) const {
  double m;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    parser_->set(knee);
    m = parser_->parser.Eval();
  }
  if (!std::isfinite(m))
    throw std::domain_error(p_.name + ": the expression is not finite (" + std::to_string(m) + ") at knee " +
                            std::to_string(knee.flexion * kRadToDeg) + " deg, " +
                            std::to_string(knee.flexionRate * kRadToDeg) + " deg/s");
  return m;
}

}  // namespace swingsim
