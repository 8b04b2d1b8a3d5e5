// deflate_runs.cpp — the run-only deflate of PNG level 1 (deflate_runs.h), written to RFC 1950
// (zlib stream) and RFC 1951 (deflate: one final block with dynamic Huffman codes, section 3.2.7).
#include "image/deflate_runs.h"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace phongvk {
namespace {

constexpr size_t MAX_MATCH = 258;
// Shortest runs worth a match; shorter ones are coded as literals. Tuned on the paper's frames:
// other minimums gave files no smaller (docs/PERFORMANCE.md, "PNG and sequences").
constexpr size_t MIN_RUN_BYTE = 4;   // distance 1: the same byte repeated (zeros: flat colour)
constexpr size_t MIN_RUN_PIXEL = 4;  // distance 3: the same filtered pixel repeated (a steady gradient)
constexpr size_t MIN_RUN_ROW = 32;   // one row back: the row above's filtered bytes (shading that varies alike)
constexpr size_t MAX_DISTANCE = 32768;

constexpr int END_OF_BLOCK = 256;
constexpr int LITLEN_SYMBOLS = 286;
constexpr int DISTANCE_SYMBOLS = 30;
constexpr int CODE_LENGTH_SYMBOLS = 19;
constexpr int MAX_CODE_BITS = 15;
constexpr int MAX_CODE_LENGTH_BITS = 7;
constexpr uint8_t CODE_LENGTH_ORDER[CODE_LENGTH_SYMBOLS] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5,
                                                            11, 4, 12, 3, 13, 2, 14, 1, 15};

// Match lengths 3..258 as deflate codes 257..285 with their extra bits (RFC 1951 3.2.5).
struct LengthCode {
  uint16_t symbol;
  uint8_t extraBits;
  uint16_t extra;
};

const std::array<LengthCode, MAX_MATCH + 1>& lengthCodes() {
  static const std::array<LengthCode, MAX_MATCH + 1> table = [] {
    constexpr uint16_t base[] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23,
                                 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227};
    constexpr uint8_t extraBits[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5};
    std::array<LengthCode, MAX_MATCH + 1> codes{};
    for (size_t code = 0; code < std::size(base); ++code) {
      for (uint32_t extra = 0; extra < (1u << extraBits[code]) && base[code] + extra < MAX_MATCH; ++extra) {
        codes[base[code] + extra] = {uint16_t(257 + code), extraBits[code], uint16_t(extra)};
      }
    }
    codes[MAX_MATCH] = {285, 0, 0};
    return codes;
  }();
  return table;
}

// Distances 1..32768 as codes 0..29 with their extra bits (RFC 1951 3.2.5).
LengthCode distanceCode(uint32_t distance) {
  uint32_t symbol = 0, base = 1, extraBits = 0;
  while (symbol < 29) {
    const uint32_t next = base + (1u << extraBits);
    if (distance < next) break;
    base = next;
    ++symbol;
    if (symbol >= 4 && symbol % 2 == 0) ++extraBits;
  }
  return {uint16_t(symbol), uint8_t(extraBits), uint16_t(distance - base)};
}

// Bytes from `at` on that repeat those `distance` back, at most `limit`, compared 16 bytes at a
// time (SSE2, every x86-64), then a word, then a byte.
size_t runLength(const uint8_t* data, size_t at, size_t distance, size_t limit) {
  const uint8_t* a = data + at;
  const uint8_t* b = a - distance;
  size_t n = 0;
#if defined(__SSE2__)
  for (; n + 16 <= limit; n += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + n));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + n));
    const unsigned differ = ~unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(x, y))) & 0xffffu;
    if (differ != 0) return n + size_t(std::countr_zero(differ));
  }
#endif
  if constexpr (std::endian::native == std::endian::little) {
    for (; n + 8 <= limit; n += 8) {
      uint64_t x, y;
      std::memcpy(&x, a + n, 8);
      std::memcpy(&y, b + n, 8);
      if (x != y) return n + size_t(std::countr_zero(x ^ y)) / 8;
    }
  }
  while (n < limit && a[n] == b[n]) ++n;
  return n;
}

// Canonical Huffman codes for code lengths (RFC 1951 3.2.2), bit-reversed: deflate writes codes
// from their first bit, and BitWriter writes from the lowest bit.
std::vector<uint16_t> canonicalCodes(const std::vector<uint8_t>& lengths) {
  std::array<uint16_t, MAX_CODE_BITS + 2> count{}, next{};
  for (uint8_t length : lengths) ++count[length];
  count[0] = 0;
  uint16_t code = 0;
  for (int bits = 1; bits <= MAX_CODE_BITS; ++bits) {
    code = uint16_t((code + count[bits - 1]) << 1);
    next[bits] = code;
  }
  std::vector<uint16_t> codes(lengths.size(), 0);
  for (size_t symbol = 0; symbol < lengths.size(); ++symbol) {
    const int length = lengths[symbol];
    if (length == 0) continue;
    const uint16_t value = next[length]++;
    uint16_t reversed = 0;
    for (int bit = 0; bit < length; ++bit) reversed = uint16_t(reversed | (((value >> bit) & 1u) << (length - 1 - bit)));
    codes[symbol] = reversed;
  }
  return codes;
}

// Bits into bytes, lowest bit first (RFC 1951 3.1.1), into `scratch` (grown to `reserve`, at most
// that many bytes, plus 8 of slack for the last partial word; kept from one image to the next, so
// a frame's bits are not written over a fresh zero fill); finish() appends them to `out`.
class BitWriter {
 public:
  BitWriter(std::vector<uint8_t>& scratch, size_t reserve, std::vector<uint8_t>& out) : out_(out), scratch_(scratch) {
    if (scratch.size() < reserve + 8) scratch.resize(reserve + 8);
  }
  void put(uint32_t value, int bits) {  // bits <= 32
    buffer_ |= uint64_t(value) << count_;
    count_ += bits;
    if (count_ >= 32) {
      const uint8_t bytes[4] = {uint8_t(buffer_), uint8_t(buffer_ >> 8), uint8_t(buffer_ >> 16), uint8_t(buffer_ >> 24)};
      std::memcpy(scratch_.data() + at_, bytes, 4);
      at_ += 4;
      buffer_ >>= 32;
      count_ -= 32;
    }
  }
  void finish() {  // to a byte boundary
    for (; count_ > 0; count_ -= 8, buffer_ >>= 8) scratch_[at_++] = uint8_t(buffer_);
    count_ = 0;
    out_.insert(out_.end(), scratch_.begin(), scratch_.begin() + ptrdiff_t(at_));
  }

 private:
  std::vector<uint8_t>& out_;
  std::vector<uint8_t>& scratch_;
  size_t at_ = 0;
  uint64_t buffer_ = 0;
  int count_ = 0;
};

struct HuffmanCode {
  std::vector<uint8_t> lengths;
  std::vector<uint16_t> codes;
  HuffmanCode(const std::vector<uint32_t>& frequencies, int limit)
      : lengths(huffmanLengths(frequencies, limit)), codes(canonicalCodes(lengths)) {}
  void put(BitWriter& out, size_t symbol) const { out.put(codes[symbol], lengths[symbol]); }
};

// The litlen and distance code lengths as code-length symbols (RFC 1951 3.2.7): 16 repeats the
// previous length 3-6 times, 17 and 18 are runs of 3-10 and 11-138 zeros. Each symbol with its
// extra bits.
struct CodeLengthSymbol {
  uint8_t symbol;
  uint8_t extra;
};

std::vector<CodeLengthSymbol> codeLengthSymbols(const std::vector<uint8_t>& lengths) {
  std::vector<CodeLengthSymbol> symbols;
  for (size_t i = 0; i < lengths.size();) {
    const uint8_t value = lengths[i];
    size_t run = 1;
    while (i + run < lengths.size() && lengths[i + run] == value) ++run;
    i += run;
    if (value == 0) {
      for (; run >= 11; run -= std::min<size_t>(run, 138)) symbols.push_back({18, uint8_t(std::min<size_t>(run, 138) - 11)});
      if (run >= 3) symbols.push_back({17, uint8_t(run - 3)}), run = 0;
    } else {
      symbols.push_back({value, 0}), --run;
      for (; run >= 3; run -= std::min<size_t>(run, 6)) symbols.push_back({16, uint8_t(std::min<size_t>(run, 6) - 3)});
    }
    for (; run > 0; --run) symbols.push_back({value, 0});
  }
  return symbols;
}

constexpr int codeLengthExtraBits(int symbol) { return symbol == 16 ? 2 : symbol == 17 ? 3 : symbol == 18 ? 7 : 0; }

// The block header: the three alphabets' sizes, the code-length code, then the litlen and
// distance code lengths in it.
void writeCodes(BitWriter& out, const HuffmanCode& litlen, const HuffmanCode& distance) {
  size_t litlenCount = LITLEN_SYMBOLS;
  while (litlenCount > 257 && litlen.lengths[litlenCount - 1] == 0) --litlenCount;
  size_t distanceCount = DISTANCE_SYMBOLS;
  while (distanceCount > 1 && distance.lengths[distanceCount - 1] == 0) --distanceCount;
  std::vector<uint8_t> all(litlen.lengths.begin(), litlen.lengths.begin() + ptrdiff_t(litlenCount));
  all.insert(all.end(), distance.lengths.begin(), distance.lengths.begin() + ptrdiff_t(distanceCount));
  const std::vector<CodeLengthSymbol> symbols = codeLengthSymbols(all);
  std::vector<uint32_t> frequencies(CODE_LENGTH_SYMBOLS, 0);
  for (const CodeLengthSymbol& s : symbols) ++frequencies[s.symbol];
  const HuffmanCode codeLengths(frequencies, MAX_CODE_LENGTH_BITS);
  int codeLengthCount = CODE_LENGTH_SYMBOLS;
  while (codeLengthCount > 4 && codeLengths.lengths[CODE_LENGTH_ORDER[codeLengthCount - 1]] == 0) --codeLengthCount;

  out.put(uint32_t(litlenCount - 257), 5);
  out.put(uint32_t(distanceCount - 1), 5);
  out.put(uint32_t(codeLengthCount - 4), 4);
  for (int i = 0; i < codeLengthCount; ++i) out.put(codeLengths.lengths[CODE_LENGTH_ORDER[i]], 3);
  for (const CodeLengthSymbol& s : symbols) {
    codeLengths.put(out, s.symbol);
    out.put(s.extra, codeLengthExtraBits(s.symbol));
  }
}

}  // namespace

std::vector<uint8_t> huffmanLengths(const std::vector<uint32_t>& frequencies, int limit) {
  // The used symbols, least frequent first (ties by symbol); at least two.
  std::vector<uint32_t> weights = frequencies;
  size_t used = size_t(std::count_if(weights.begin(), weights.end(), [](uint32_t f) { return f > 0; }));
  for (size_t s = 0; used < 2 && s < weights.size(); ++s) {
    if (weights[s] == 0) weights[s] = 1, ++used;
  }
  std::vector<uint32_t> symbols;
  for (uint32_t s = 0; s < weights.size(); ++s) {
    if (weights[s] > 0) symbols.push_back(s);
  }
  std::stable_sort(symbols.begin(), symbols.end(), [&](uint32_t a, uint32_t b) { return weights[a] < weights[b]; });

  // Huffman's tree with two queues: leaves 0..m-1 in order, then internal nodes in the order
  // they are made (their weights never decrease). A node's parent always comes after it.
  const size_t m = symbols.size();
  std::vector<uint64_t> weight(2 * m - 1);
  std::vector<size_t> parent(2 * m - 1, 0);
  for (size_t i = 0; i < m; ++i) weight[i] = weights[symbols[i]];
  size_t leaf = 0, inner = m;
  for (size_t made = m; made < 2 * m - 1; ++made) {
    size_t pair[2];
    for (size_t& pick : pair) pick = (leaf < m && (inner >= made || weight[leaf] <= weight[inner])) ? leaf++ : inner++;
    weight[made] = weight[pair[0]] + weight[pair[1]];
    parent[pair[0]] = parent[pair[1]] = made;
  }
  std::vector<size_t> depth(2 * m - 1, 0);
  for (size_t node = 2 * m - 1; node-- > 0;) {
    if (node != 2 * m - 2) depth[node] = depth[parent[node]] + 1;
  }

  // Codes per length, the longest folded into `limit`, then rebalanced until the code is
  // complete again: take a code of the longest length away, and split a shorter one in two.
  std::vector<size_t> count(std::max<size_t>(size_t(limit), *std::max_element(depth.begin(), depth.begin() + ptrdiff_t(m))) + 1, 0);
  for (size_t i = 0; i < m; ++i) ++count[depth[i]];
  for (size_t length = size_t(limit) + 1; length < count.size(); ++length) count[size_t(limit)] += count[length], count[length] = 0;
  uint64_t kraft = 0;  // sum of 2^(limit - length): 2^limit when the code is complete
  for (int length = 1; length <= limit; ++length) kraft += uint64_t(count[size_t(length)]) << (limit - length);
  for (; kraft > (uint64_t(1) << limit); --kraft) {
    --count[size_t(limit)];
    for (int length = limit - 1; length > 0; --length) {
      if (count[size_t(length)] == 0) continue;
      --count[size_t(length)];
      count[size_t(length) + 1] += 2;
      break;
    }
  }

  // The longest codes to the least frequent symbols.
  std::vector<uint8_t> lengths(frequencies.size(), 0);
  size_t next = 0;
  for (int length = limit; length >= 1; --length) {
    for (size_t k = 0; k < count[size_t(length)]; ++k) lengths[symbols[next++]] = uint8_t(length);
  }
  return lengths;
}

void RunDeflater::deflate(const uint8_t* data, size_t size, size_t rowBytes, std::vector<uint8_t>& out) {
  // Pass 1: literals and runs, and how often each symbol occurs.
  tokens.clear();
  std::vector<uint32_t> litlenFrequencies(LITLEN_SYMBOLS, 0), distanceFrequencies(DISTANCE_SYMBOLS, 0);
  const auto& lengths = lengthCodes();
  // The three distances tried, in order: a byte, a pixel, a row back (rows longer than deflate's
  // window go without).
  const std::array<LengthCode, 3> distanceCodes = {distanceCode(1), distanceCode(3), distanceCode(uint32_t(std::min(rowBytes, MAX_DISTANCE)))};
  // Most positions that start no run differ from the byte `distance` back within the first 4
  // bytes (every minimum is at least 4), so one 32-bit comparison turns them away before the
  // run is measured: a frame's literals are a twentieth of its bytes but most of the tries.
  const auto tryRun = [&](size_t at, size_t distance, size_t minimum, size_t limit) -> size_t {
    if (at < distance || distance > MAX_DISTANCE || limit < minimum) return 0;
    uint32_t here, back;
    std::memcpy(&here, data + at, 4);
    std::memcpy(&back, data + at - distance, 4);
    if (here != back) return 0;
    const size_t run = runLength(data, at, distance, limit);
    return run >= minimum ? run : 0;
  };
  size_t literalsFrom = 0;
  for (size_t at = 0; at < size;) {
    const size_t limit = std::min(MAX_MATCH, size - at);
    size_t run = 0, which = 0;
    if ((run = tryRun(at, 1, MIN_RUN_BYTE, limit)) != 0) which = 0;
    else if ((run = tryRun(at, 3, MIN_RUN_PIXEL, limit)) != 0) which = 1;
    else if ((run = tryRun(at, rowBytes, MIN_RUN_ROW, limit)) != 0) which = 2;
    if (run == 0) {  // a literal, counted as it is passed
      ++litlenFrequencies[data[at]];
      ++at;
      continue;
    }
    tokens.push_back({uint32_t(at - literalsFrom), uint16_t(run), uint16_t(which)});
    ++litlenFrequencies[lengths[run].symbol];
    ++distanceFrequencies[distanceCodes[which].symbol];
    at += run;
    literalsFrom = at;
  }
  tokens.push_back({uint32_t(size - literalsFrom), 0, 0});
  ++litlenFrequencies[END_OF_BLOCK];

  // Pass 2: the zlib header, the block, the checksum.
  const HuffmanCode litlen(litlenFrequencies, MAX_CODE_BITS);
  const HuffmanCode distances(distanceFrequencies, MAX_CODE_BITS);
  out.insert(out.end(), {0x78, 0x01});  // deflate, 32 KiB window, no dictionary, "fastest" (RFC 1950)
  // Room for the block: the header's code lengths, then at most 15 bits a literal and 48 a run
  // (length code and extra bits, distance code and extra bits), and the end of block.
  size_t literalCount = 0;
  for (const RunToken& token : tokens) literalCount += token.literals;
  BitWriter bits(scratch, 1024 + (literalCount * 15 + tokens.size() * 48) / 8, out);
  bits.put(1, 1);  // the final block
  bits.put(2, 2);  // dynamic Huffman codes
  writeCodes(bits, litlen, distances);
  const uint8_t* next = data;
  for (const RunToken& token : tokens) {
    for (const uint8_t* end = next + token.literals; next < end; ++next) litlen.put(bits, *next);
    if (token.length == 0) continue;
    const LengthCode& code = lengths[token.length];
    litlen.put(bits, code.symbol);
    bits.put(code.extra, code.extraBits);
    const LengthCode& distance = distanceCodes[token.distance];
    distances.put(bits, distance.symbol);
    bits.put(distance.extra, distance.extraBits);
    next += token.length;
  }
  litlen.put(bits, END_OF_BLOCK);
  bits.finish();
  const uint32_t adler = libdeflate_adler32(1, data, size);
  out.insert(out.end(), {uint8_t(adler >> 24), uint8_t(adler >> 16), uint8_t(adler >> 8), uint8_t(adler)});
}

}  // namespace phongvk
