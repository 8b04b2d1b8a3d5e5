#include "api/timing.h"

#include "phongvk/phongvk.h"

#include <algorithm>
#include <limits>

namespace phongvk {

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

FrameTimes timeFrames(int repeat, const std::function<double()>& frame) {
  frame();
  FrameTimes times;
  for (int i = 0; i < repeat; ++i) {
    const auto start = Clock::now();
    const double deviceMs = frame();
    times.wallMs.push_back(msSince(start));
    times.deviceMs.push_back(deviceMs);
  }
  return times;
}

}  // namespace phongvk
