// number_text.h — numbers as messages print them.
#pragma once

#include <string>

namespace phongvk {

// Shortest text that reads back as the same number: "-1", "0.05", "1e+300". The float
// overload prints a float field's value as written (0.1f as "0.1", not "0.10000000149011612").
std::string formatNumber(double value);
std::string formatNumber(float value);

}  // namespace phongvk
