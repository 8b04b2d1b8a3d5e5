// statistics.h — summaries of repeated timings, as the CLI and the benchmark report them.
#pragma once

#include <vector>

namespace phongvk {

// The middle value (the mean of the two middle ones for an even count); NaN for no values. Robust
// to the odd slow run a shared machine produces.
double median(std::vector<double> values);

}  // namespace phongvk
