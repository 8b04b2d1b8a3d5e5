// expression.cpp — a recursive-descent evaluator, one function per precedence level:
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('-' | '+') unary | power
//   power   := primary ('^' unary)?            right-associative; 2^-1 is allowed
//   primary := number | name | name '(' sum (',' sum)* ')' | '(' sum ')'
#include "scene/expression.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

namespace phongvk {
namespace {

struct Function {
  std::string_view name;
  int arity;
  double (*apply)(const double* args);
};

const std::array<Function, 12> kFunctions = {{
    {"sin", 1, [](const double* a) { return std::sin(a[0]); }},
    {"cos", 1, [](const double* a) { return std::cos(a[0]); }},
    {"tan", 1, [](const double* a) { return std::tan(a[0]); }},
    {"asin", 1, [](const double* a) { return std::asin(a[0]); }},
    {"acos", 1, [](const double* a) { return std::acos(a[0]); }},
    {"atan", 1, [](const double* a) { return std::atan(a[0]); }},
    {"sqrt", 1, [](const double* a) { return std::sqrt(a[0]); }},
    {"abs", 1, [](const double* a) { return std::abs(a[0]); }},
    {"floor", 1, [](const double* a) { return std::floor(a[0]); }},
    {"min", 2, [](const double* a) { return std::min(a[0], a[1]); }},
    {"max", 2, [](const double* a) { return std::max(a[0], a[1]); }},
    {"pow", 2, [](const double* a) { return std::pow(a[0], a[1]); }},
}};

// Deep enough for any real expression; shallow enough that hostile input ("((((...") cannot
// exhaust the stack.
constexpr int kMaxNesting = 64;

// 'word', quoted for messages.
std::string quoted(std::string_view word) {
  std::string text = "'";
  text.append(word).append("'");
  return text;
}

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isNumberStart(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.'; }

class Parser {
 public:
  Parser(std::string_view text, const ExpressionVariables& variables) : text_(text), vars_(variables) {}

  double parse() {
    skipSpace();
    if (atEnd()) fail("empty expression", 0);
    double value = sum();
    if (!atEnd()) failUnexpected();
    return value;
  }

 private:
  double sum() {
    double value = product();
    while (true) {
      if (accept('+')) value += product();
      else if (accept('-')) value -= product();
      else return value;
    }
  }

  double product() {
    double value = unary();
    while (true) {
      if (accept('*')) value *= unary();
      else if (accept('/')) value /= unary();
      else return value;
    }
  }

  double unary() {
    const Nesting nesting(*this);
    if (accept('-')) return -unary();
    if (accept('+')) return unary();
    return power();
  }

  double power() {
    double base = primary();
    if (accept('^')) return std::pow(base, unary());
    return base;
  }

  double primary() {
    if (atEnd()) fail("unexpected end of expression", pos_);
    if (accept('(')) {
      double value = sum();
      expect(')');
      return value;
    }
    if (isNumberStart(peek())) return number();
    if (isNameStart(peek())) return name();
    failUnexpected();
  }

  double number() {
    const size_t start = pos_;
    double value = 0;
    auto [end, error] = std::from_chars(text_.data() + pos_, text_.data() + text_.size(), value);
    if (error == std::errc::result_out_of_range) fail("number out of range", start);
    if (error != std::errc()) fail("malformed number", start);
    pos_ = end - text_.data();
    skipSpace();
    return value;
  }

  double name() {
    const size_t start = pos_;
    while (!atEnd() && isNameChar(text_[pos_])) ++pos_;
    const std::string_view word = text_.substr(start, pos_ - start);
    skipSpace();
    if (accept('(')) return call(word, start);
    if (word == "i") return vars_.i;
    if (word == "n") return vars_.n;
    if (word == "pi") return std::numbers::pi;
    if (findFunction(word)) fail(quoted(word) + " is a function: write " + std::string(word) + "(...)", start);
    fail("unknown variable " + quoted(word) + " (known: i, n, pi)", start);
  }

  // After "name(": the arguments, the closing parenthesis, and the call.
  double call(std::string_view word, size_t start) {
    const Function* function = findFunction(word);
    if (!function) fail("unknown function " + quoted(word), start);
    std::vector<double> args = {sum()};
    while (accept(',')) args.push_back(sum());
    expect(')');
    if (int(args.size()) != function->arity) {
      fail(quoted(word) + " takes " + std::to_string(function->arity) + " argument" +
               (function->arity == 1 ? "" : "s") + ", got " + std::to_string(args.size()),
           start);
    }
    return function->apply(args.data());
  }

  static const Function* findFunction(std::string_view word) {
    for (const Function& f : kFunctions) {
      if (f.name == word) return &f;
    }
    return nullptr;
  }

  // Counts how deep unary() (hence every parenthesis and operand) is nested.
  struct Nesting {
    explicit Nesting(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxNesting) parser.fail("nested too deeply", parser.pos_);
    }
    ~Nesting() { --parser.depth_; }
    Parser& parser;
  };

  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }

  void skipSpace() {
    while (!atEnd() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  bool accept(char c) {
    if (atEnd() || peek() != c) return false;
    ++pos_;
    skipSpace();
    return true;
  }

  void expect(char c) {
    if (accept(c)) return;
    if (atEnd()) fail(std::string("expected '") + c + "' before the end of the expression", pos_);
    fail(std::string("expected '") + c + "', got '" + peek() + "'", pos_);
  }

  [[noreturn]] void failUnexpected() const { fail(std::string("unexpected '") + peek() + "'", pos_); }

  [[noreturn]] void fail(const std::string& what, size_t offset) const {
    throw ExpressionError(what + " at column " + std::to_string(offset + 1));
  }

  std::string_view text_;
  const ExpressionVariables& vars_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

double evaluateExpression(std::string_view text, const ExpressionVariables& variables) {
  return Parser(text, variables).parse();
}

}  // namespace phongvk
