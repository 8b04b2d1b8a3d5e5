// expression.h — the small arithmetic language of animation tracks, e.g. "5*cos(2*pi*i/n)".
//
// Numbers, the variables i (frame index), n (frame count) and pi, + - * / ^ and parentheses, and
// the functions sin cos tan asin acos atan sqrt abs floor (one argument) and min max pow (two).
// Precedence, loosest first: + -, then * /, then unary minus, then ^ (right-associative), so
// -2^2 = -4, 2^3^2 = 512 and 2^-1 = 0.5, as in mathematics and Python's **. Nothing else is
// understood: there are no other names and nothing is executed.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace phongvk {

// A malformed expression. what() says what and where, e.g. "unknown function 'sine' at column 3"
// (columns count bytes from 1).
class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExpressionVariables {
  double i = 0;  // frame index
  double n = 1;  // frame count
};

// Parses and evaluates `text`. The result may be NaN or infinite (sqrt(-1), 1/0); callers that
// need a finite number check it. Throws ExpressionError for anything that is not an expression.
double evaluateExpression(std::string_view text, const ExpressionVariables& variables);

}  // namespace phongvk
