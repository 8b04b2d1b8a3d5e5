// text_words.h — the words of a line of a text mesh file (OBJ, ASCII PLY): runs of characters
// between whitespace, as views into the line.
#pragma once

#include <cctype>
#include <string_view>
#include <vector>

namespace phongvk {

inline void appendWords(std::string_view line, std::vector<std::string_view>& words) {
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
}

}  // namespace phongvk
