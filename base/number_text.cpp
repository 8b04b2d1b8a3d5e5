#include "base/number_text.h"

#include <charconv>

namespace phongvk {
namespace {

template <typename Real>
std::string shortestText(Real value) {
  char buffer[32];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::string formatNumber(double value) { return shortestText(value); }
std::string formatNumber(float value) { return shortestText(value); }

}  // namespace phongvk
