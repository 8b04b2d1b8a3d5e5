// text.h — number formatting for the benchmark's progress lines and report.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace phongvk::bench {

// printf into a std::string.
template <typename... Args>
std::string formatText(const char* pattern, Args... args) {
  const int size = std::snprintf(nullptr, 0, pattern, args...);
  std::string text(size_t(size > 0 ? size : 0), '\0');
  std::snprintf(text.data(), text.size() + 1, pattern, args...);
  return text;
}

// `value` with `decimals` decimals, or an en dash for a value that was not measured (NaN).
inline std::string number(double value, int decimals) {
  if (std::isnan(value)) return "–";
  if (std::isinf(value)) return value > 0 ? "∞" : "-∞";
  return formatText("%.*f", decimals, value);
}

}  // namespace phongvk::bench
