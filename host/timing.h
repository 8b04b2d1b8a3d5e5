// timing.h — timing repeated frames: one warm-up, then N timed runs, summarised by the median
// (robust to the odd slow run a shared machine produces). Used by `phongvk render --repeat` and
// the benchmark (bench/).
#pragma once

#include <functional>
#include <vector>

namespace phongvk {

struct FrameTimes {
  std::vector<double> wallMs;    // per timed run, wall clock around the call
  std::vector<double> deviceMs;  // per timed run, what the call returned (NaN when it has none)
};

// The middle value (the mean of the two middle ones for an even count); NaN for no values.
double median(std::vector<double> values);

// Calls `frame` once untimed — first-use costs (pipeline caches, page faults, lazy allocation)
// are not a frame's — then `repeat` times, timing each. `frame` returns its device time in ms.
FrameTimes timeFrames(int repeat, const std::function<double()>& frame);

}  // namespace phongvk
