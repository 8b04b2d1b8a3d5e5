#include "api/timing.h"

#include "phongvk/phongvk.h"

#include <algorithm>
#include <limits>

namespace phongvk {

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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
