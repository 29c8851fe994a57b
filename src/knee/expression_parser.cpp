#include "knee/expression_parser.h"

#include <muParser.h>

#include <cmath>
#include <set>

#include "core/identifier.h"

namespace swingsim {

// muparser reads the variables and parameters through pointers: they live here.
struct ExpressionParser::Impl {
  mu::Parser parser;
  std::vector<double> state, parameters;
};

namespace {

std::string variableList(const std::vector<KneeExpressionVariable>& variables) {
  std::string out;
  for (const auto& v : variables) out += (out.empty() ? "" : ", ") + std::string(v.name);
  return out;
}

void checkParameterNames(const KneeExpressionParams& p, const std::vector<KneeExpressionVariable>& variables) {
  std::set<std::string> seen;
  for (const auto& q : p.parameters) {
    if (!isIdentifier(q.name))
      throw KneeExpressionError(
          "parameter '" + q.name + "': expected a name of letters, digits and _, not starting with a digit", -1);
    for (const auto& v : variables)
      if (q.name == v.name)
        throw KneeExpressionError(
            "parameter '" + q.name + "': the name of a state variable (" + variableList(variables) + ")", -1);
    if (!seen.insert(q.name).second) throw KneeExpressionError("parameter '" + q.name + "' is named twice", -1);
    if (!std::isfinite(q.value)) throw KneeExpressionError("parameter '" + q.name + "': expected a finite value", -1);
  }
}

KneeExpressionError fromParser(const mu::Parser::exception_type& e,
                               const std::vector<KneeExpressionVariable>& variables) {
  std::string message = e.GetMsg();
  if (message.find("Unexpected token") != std::string::npos && !e.GetToken().empty())
    message += " (a name must be a state variable: " + variableList(variables) + "; or one of the parameters)";
  return KneeExpressionError(message, e.GetPos());
}

}  // namespace

std::string describeKneeExpressionError(const std::string& expression, const KneeExpressionError& error) {
  std::string out = error.what();
  const int at = error.position();
  if (at >= 0 && static_cast<std::size_t>(at) <= expression.size())
    out += " (character " + std::to_string(at + 1) + " of the expression: \"" +
           expression.substr(static_cast<std::size_t>(at)) + "\")";
  return out;
}

ExpressionParser::ExpressionParser(const KneeExpressionParams& p, const std::vector<KneeExpressionVariable>& variables)
    : impl_(std::make_unique<Impl>()) {
  impl_->state.assign(variables.size(), 0.0);
  impl_->parameters.resize(p.parameters.size());
  try {
    for (std::size_t i = 0; i < variables.size(); ++i) impl_->parser.DefineVar(variables[i].name, &impl_->state[i]);
    for (std::size_t i = 0; i < p.parameters.size(); ++i) {
      impl_->parameters[i] = p.parameters[i].value;
      impl_->parser.DefineVar(p.parameters[i].name, &impl_->parameters[i]);
    }
    impl_->parser.SetExpr(p.expression);
    impl_->parser.Eval();  // muparser parses on the first evaluation: its errors come here
  } catch (const mu::Parser::exception_type& e) {
    throw fromParser(e, variables);
  }
}

ExpressionParser::~ExpressionParser() = default;

double* ExpressionParser::state() { return impl_->state.data(); }

double ExpressionParser::eval() { return impl_->parser.Eval(); }

std::set<std::string> ExpressionParser::usedNames() const {
  std::set<std::string> out;
  for (const auto& [name, where] : impl_->parser.GetUsedVar()) out.insert(name);
  return out;
}

void checkExpression(const KneeExpressionParams& p, const std::vector<KneeExpressionVariable>& variables,
                     const std::string& quantity) {
  checkParameterNames(p, variables);
  if (p.expression.find_first_not_of(" \t\r\n") == std::string::npos)
    throw KneeExpressionError("expected an expression of " + quantity + ", found an empty text", -1);
  const ExpressionParser parser(p, variables);
  const std::set<std::string> used = parser.usedNames();
  for (const auto& q : p.parameters)
    if (used.find(q.name) == used.end())
      throw KneeExpressionError("parameter '" + q.name + "' is not used by the expression: it could not be fitted", -1);
}

}  // namespace swingsim
