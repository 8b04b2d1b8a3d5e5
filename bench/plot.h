// plot.h — the error sweep's run time against error chart, drawn by gnuplot (a Debian package,
// installed by scripts/setup.sh --test).
#pragma once

#include "error_sweep.h"

#include <string>

namespace phongvk::bench {

// Writes the chart of compute cost against RMSE (UV spheres, icospheres, the Pareto front) to
// `pngPath`. Returns an empty string when it was written, otherwise why not, so the report can say
// so instead of linking a stale picture.
std::string plotErrorSweep(const SweepResult& sweep, const std::string& pngPath, const std::string& deviceName);

}  // namespace phongvk::bench
