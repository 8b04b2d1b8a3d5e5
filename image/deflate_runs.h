// deflate_runs.h — PNG level 1: a zlib stream that codes only runs (deflate matches at distance 1,
// 3 or one row: a byte, a filtered pixel or the row above repeated) and literals, in one block with Huffman codes fitted
// to the image. A rendered frame filtered "Sub" is almost all zero bytes in long runs (flat
// background, shading that changes by less than one 8-bit step from pixel to pixel), so finding
// the runs a word at a time and coding the rest is much faster than a general match finder's
// fastest level, for somewhat larger files (docs/DECISIONS.md "PNG levels", docs/PERFORMANCE.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phongvk {

// A stretch of literals and the run after it: `literals` bytes coded as they are, then `length`
// (0, or 3 to 258) bytes repeating those a byte, a pixel or a row back (`distance` 0, 1 or 2).
struct RunToken {
  uint32_t literals;
  uint16_t length;
  uint16_t distance;
};

// Buffers kept from one image to the next (PngEncoder holds one).
struct RunDeflater {
  std::vector<RunToken> tokens;
  std::vector<uint8_t> scratch;  // the block's bits before they are appended to the stream
  // Appends the zlib stream (header, one final dynamic-Huffman block, Adler-32) of `size` bytes in
  // rows of `rowBytes`.
  void deflate(const uint8_t* data, size_t size, size_t rowBytes, std::vector<uint8_t>& out);
};

// Code lengths (0 for an unused symbol, at most `limit`) of a Huffman code for these symbol
// frequencies; at least two symbols get a code, so the code is complete. Ties break by symbol, so
// the same frequencies always give the same lengths.
std::vector<uint8_t> huffmanLengths(const std::vector<uint32_t>& frequencies, int limit);

}  // namespace phongvk
