// The expression parser both users' expressions share (knee/expression_parser.h).
#include "knee/expression_parser.h"

#include <gtest/gtest.h>

namespace swingsim {
namespace {

const std::vector<KneeExpressionVariable> kVars = {{"x", "a position"}, {"v", "a speed"}};

TEST(ExpressionParser, EvaluatesAtTheStateItIsGiven) {
  ExpressionParser p({"e", "a * x + v^2 - max(0, x - 1)", {{"a", "", 2.0}}}, kVars);
  p.state()[0] = 3;
  p.state()[1] = 0.5;
  EXPECT_DOUBLE_EQ(p.eval(), 2 * 3 + 0.25 - 2);
  p.state()[0] = 0.5;
  EXPECT_DOUBLE_EQ(p.eval(), 1 + 0.25);
  EXPECT_EQ(p.usedNames(), (std::set<std::string>{"a", "v", "x"}));
}

TEST(ExpressionParser, RefusesWithTheCharacterWhereItStopped) {
  try {
    checkExpression({"e", "a * y", {{"a", "", 1.0}}}, kVars, "a test quantity");
    ADD_FAILURE() << "an unknown name was accepted";
  } catch (const KneeExpressionError& e) {
    EXPECT_EQ(e.position(), 4);
    const std::string line = describeKneeExpressionError("a * y", e);
    EXPECT_NE(line.find("x, v"), std::string::npos) << line;  // names the variables it knows
    EXPECT_NE(line.find("character 5"), std::string::npos) << line;
  }
  EXPECT_THROW(checkExpression({"e", " ", {{"a", "", 1.0}}}, kVars, "q"), KneeExpressionError);  // empty
  EXPECT_THROW(checkExpression({"e", "x", {{"a", "", 1.0}}}, kVars, "q"), KneeExpressionError);  // a unused
  EXPECT_THROW(checkExpression({"e", "x * x", {{"x", "", 1.0}}}, kVars, "q"),
               KneeExpressionError);  // a variable's name
  EXPECT_THROW(checkExpression({"e", "a * x", {{"a", "", 1.0}, {"a", "", 2.0}}}, kVars, "q"), KneeExpressionError);
  EXPECT_THROW(checkExpression({"e", "a * x", {{"2a", "", 1.0}}}, kVars, "q"), KneeExpressionError);
  EXPECT_NO_THROW(checkExpression({"e", "a * x", {{"a", "", 1.0}}}, kVars, "q"));
}

}  // namespace
}  // namespace swingsim
