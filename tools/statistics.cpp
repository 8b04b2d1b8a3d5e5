// statistics.cpp — see statistics.h.
#include "tools/statistics.h"

#include <algorithm>
#include <limits>

namespace phongvk {

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace phongvk
