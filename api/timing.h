// timing.h — timing repeated frames: one warm-up, then N timed runs (Renderer::timeFrames and the
// benchmark, bench/, time their frames with it).
#pragma once

#include <chrono>
#include <functional>
#include <vector>

namespace phongvk {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start);

struct FrameTimes {
  std::vector<double> wallMs;    // per timed run, wall clock around the call
  std::vector<double> deviceMs;  // per timed run, what the call returned (NaN when it has none)
};

// Calls `frame` once untimed — first-use costs (pipeline caches, page faults, lazy allocation)
// are not a frame's — then `repeat` times, timing each. `frame` returns its device time in ms.
FrameTimes timeFrames(int repeat, const std::function<double()>& frame);

}  // namespace phongvk
