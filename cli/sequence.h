// sequence.h — `phongvk sequence`'s frame selection and file names.
#pragma once

#include <string>

namespace phongvk::cli {

// The frames start, start + step, ... below end.
struct FrameRange {
  int start = 0;
  int end = 0;
  int step = 1;
  int count() const { return 1 + (end - start - 1) / step; }  // precondition: start < end
};

// Reads --frames like a Python slice of the sequence's frames: START:END or START:END:STEP,
// END excluded, START defaulting to 0, END to frameCount, STEP to 1. Unlike Python, indices are
// never negative and never clamped: START < END <= frameCount, or UsageError says why.
FrameRange parseFrameRange(const std::string& text, int frameCount);

// The file frame `index` is written to: "<dir>/frame_0007.png" (4 digits, more when the
// sequence has more than 10000 frames).
std::string framePath(const std::string& dir, int index, int frameCount);

}  // namespace phongvk::cli
