// text.h — number formatting and markdown table rows for the benchmark's progress lines and report.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

// One markdown table row.
inline std::string row(const std::vector<std::string>& cells) {
  std::string text = "|";
  for (const std::string& c : cells) text += " " + c + " |";
  return text + "\n";
}

// A table's header row and the separator under it: the first column left-aligned, the others
// right-aligned when they hold numbers.
inline std::string header(const std::vector<std::string>& cells, bool numbers = true) {
  std::string separator = "|";
  for (size_t i = 0; i < cells.size(); ++i) separator += i == 0 || !numbers ? "---|" : "--:|";
  return row(cells) + separator + "\n";
}

}  // namespace phongvk::bench
