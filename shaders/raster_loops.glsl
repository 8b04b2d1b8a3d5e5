// raster_loops.glsl — what the raster passes share (after bindings.glsl): offering keys, bin
// marking, span loops, handing large triangles to resolve.
#include "large_triangles.h"
#include "row_spans.h"
#include "small_triangles.h"

// Which of the key's words this dispatch decides (shared.h KEY_PASS_*). With 64-bit atomics, the
// whole key at once (atomicMin). On the 32-bit key path, the triangle and clip passes run twice:
// KEY_PASS_DEPTH takes the smallest depth word (the key's high word) of each pixel, then
// KEY_PASS_IDS, among the fragments whose depth word equals it, the smallest triangle id (the low
// word). That is the smallest 64-bit key's pair of words: its high word is the least high word,
// and among keys with that high word the least low word (docs/DESIGN.md "Visibility"). Only the
// depth pass lists triangles for the clip pass, marks bins and defers large triangles to resolve;
// the ids pass redraws the pixels the depth pass drew, of the triangle pass's small triangles only
// those it kept (keepTriangle).
#ifdef PHONGVK_KEYS32
layout(constant_id = SPEC_KEY_PASS) const uint KEY_PASS = KEY_PASS_DEPTH;
#else
const uint KEY_PASS = KEY_PASS_WHOLE;
#endif
const bool IDS_PASS = KEY_PASS == KEY_PASS_IDS;

// A fragment's key offered to pixel i: the pixel keeps the smallest. True where the fragment may
// still win the pixel: on the 32-bit key path's depth pass, where its depth word is at most the one
// the pixel held before it (a larger word can never equal the least the pixel ends with); true
// wherever else.
bool offerKey(uint i, VisibilityKey key) {
#ifdef PHONGVK_KEYS32
  if (!IDS_PASS) return keyHigh(key) <= atomicMin(keyPairs[i].y, keyHigh(key));
  if (keyPairs[i].y == keyHigh(key)) atomicMin(keyPairs[i].x, keyLow(key));
#else
  atomicMin(keys[i], key);
#endif
  return true;
}

// The pixels of a box, (x1 - x0 + 1) (y1 - y0 + 1).
int boxPixels(ivec4 box) { return (box.z - box.x + 1) * (box.w - box.y + 1); }

// Fan sub-triangle (0, b, c) of a clipped polygon as a triangle setup of its own (same plane,
// depth range and id; its own box), so later passes only ever see count == 3 and index constantly.
TriangleSetup fanSubTriangle(TriangleSetup t, ivec2 b, ivec2 c) {
  TriangleSetup sub = t;
  sub.count = 3;
  sub.snapped[1] = b;
  sub.snapped[2] = c;
  ivec2 a = sub.snapped[0];
  sub.bbox = pixelBounds(min(a, min(b, c)), max(a, max(b, c)), frame.width, frame.height);
  return sub;
}

// Vertex i of a set-up polygon, picked with constant indices (a per-lane index would put the
// polygon in memory on a SIMD device, and lengthen lavapipe's code generation by seconds).
ivec2 snappedAt(TriangleSetup t, int i) {
  ivec2 v = t.snapped[0];
  [[unroll]] for (int j = 1; j < int(MAX_CLIP_VERTICES); ++j) v = i == j ? t.snapped[j] : v;
  return v;
}

// Fan sub-triangle k (0, k + 1, k + 2) of a polygon of any count.
TriangleSetup fanTriangle(TriangleSetup t, int k) { return fanSubTriangle(t, snappedAt(t, k + 1), snappedAt(t, k + 2)); }

// The only sub-triangle of an unclipped triangle (count == 3), with constant indices.
bool setupSingle(TriangleSetup t, out EdgeSetup s) {
  return setupEdges(t.snapped[0], t.snapped[1], t.snapped[2], t.frontFacing != 0u, frame.width, frame.height, s);
}

// Records that bin b needs resolving, with `flags` (the tiles whose keys were written, if any):
// the first toucher appends it to the touched list (the plain read skips the atomics for bins
// already marked so).
void touchBin(uvec2 b, uint flags) {
  uint bin = b.y * control.binsX + b.x;
  uint want = BIN_LISTED | flags;
  if ((binData[bin] & want) == want) return;
  if ((atomicOr(binData[bin], want) & BIN_LISTED) != 0u) return;
  uint k = atomicAdd(binList.count, 1u);
  binData[2u * control.binCount + k] = b.x | (b.y << 16);  // resolve needs no division
  atomicMax(binList.groupsX, min(k + 1u, control.groupCap));
}

// The bins of pixel box (x0, y0, x1, y1), as (bx0, by0, bx1, by1).
ivec4 binsOf(ivec4 box) { return box / int(BIN_SIZE); }

// Marks the tiles of pixel box as touched by a triangle whose keys went into the key buffer.
void markBins(ivec4 box) {
  ivec4 tiles = box / int(TILE_SIZE);
  ivec4 bins = tiles / int(BIN_TILES);
  for (int by = bins.y; by <= bins.w; ++by) {
    for (int bx = bins.x; bx <= bins.z; ++bx) {
      ivec4 inBin = clamp(tiles - ivec4(bx, by, bx, by) * int(BIN_TILES), 0, int(BIN_TILES) - 1);
      touchBin(uvec2(bx, by), binTileRect(inBin) << BIN_KEYS_SHIFT);
    }
  }
}

// Rasterizes sub-triangle s, row span by row span, one invocation. True where one of its fragments
// may still win (offerKey).
bool rasterizeRows(TriangleSetup t, EdgeSetup s) {
  bool mayWin = false;
  for (int y = s.bbox.y; y <= s.bbox.w; ++y) {
    ivec2 span = rowSpan(s, y);
    for (int x = span.x; x <= span.y; ++x) {
      mayWin = offerKey(uint(y) * frame.width + uint(x), coveredKey(t, x, y, frame)) || mayWin;
    }
  }
  return mayWin;
}

// In a scene of fewer than KEPT_LIST_BELOW triangles (gpu_layout.h keptList) on the 32-bit key
// path, the kept triangles as a list after the words, walked a triangle an invocation by an
// indirect dispatch; never on the 64-bit path, which keeps none.
#ifdef PHONGVK_KEYS32
layout(constant_id = SPEC_KEPT_LIST) const bool KEPT_LIST = false;
#else
const bool KEPT_LIST = false;
#endif
uint keptListIndex(uint k) { return control.triangleCount + keptWords(control.triangleCount) + k; }

// The clip pass's kept triangles (keptList scenes), listed from the list's room's end down, as
// the triangle pass's are from its start up (gpu_layout.h IdList): its depth dispatch keeps each
// clip-listed triangle that drew a fragment that may still win, its ids dispatch draws only those.
uint keptClippedIndex(uint k) { return keptListIndex(control.triangleCount - 1u - k); }

void keepClipped(uint id) {
  uint k = atomicAdd(clipList.keptClipped, 1u);
  clipIds[keptClippedIndex(k)] = id;
  atomicMax(clipList.clipIdsGroupsX, min(k / CLIP_GROUP_SIZE + 1u, control.groupCap));
}

#ifdef PHONGVK_KEYS32
// The triangle pass's kept triangles on the 32-bit key path (gpu_layout.h keptWords). Its depth
// pass keeps each small triangle with a fragment that may still win a pixel; its ids pass draws
// only those, a chunk of them an invocation (gpu_layout.h keptSpan): a triangle none of whose
// fragments may win cannot hold any pixel's least depth word, so leaving it out changes no pixel.
uint keptWordIndex(uint w) { return control.triangleCount + w; }

void keepTriangle(uint id) {
  if (!KEPT_LIST) {
    atomicOr(clipIds[keptWordIndex(id / 32u)], 1u << (id % 32u));
    return;
  }
  uint k = atomicAdd(clipList.keptListed, 1u);
  clipIds[keptListIndex(k)] = id;
  atomicMax(clipList.idsGroupsX, min(k / SETUP_GROUP_SIZE + 1u, control.groupCap));
}

// Chunk c's kept bits (keptSpan of them, from triangle c * span on), in its word's low bits.
uint keptChunkBits(uint c, uint span) {
  uint first = c * span;
  uint bits = clipIds[keptWordIndex(first / 32u)] >> (first % 32u);
  return span < 32u ? bits & ((1u << span) - 1u) : bits;
}
#endif

// A small sub-triangle's pixels (small_triangles.h setupSmallEdges), one invocation: every pixel of
// its box tested (coversSmall), as the reference does, which on lavapipe is faster than row spans
// (docs/PERFORMANCE.md, "History"). True where one of its fragments may still win (offerKey).
bool rasterizeSmall(TriangleSetup t, EdgeSetup s) {
  bool mayWin = false;
  for (int y = s.bbox.y; y <= s.bbox.w; ++y) {
    for (int x = s.bbox.x; x <= s.bbox.z; ++x) {
      if (coversSmall(s, x, y)) mayWin = offerKey(uint(y) * frame.width + uint(x), coveredKey(t, x, y, frame)) || mayWin;
    }
  }
  return mayWin;
}

// Reserves `count` of a list's slots unless that would pass `capacity`; LIST_END if not. The
// plain read first keeps a full list's counter from growing (and wrapping) frame after frame.
uint reserve(uint count, uint capacity, bool entries) {
  uint used = entries ? large.count : large.setups;
  if (used >= capacity || count > capacity - used) return LIST_END;
  uint first = entries ? atomicAdd(large.count, count) : atomicAdd(large.setups, count);
  return first < capacity && count <= capacity - first ? first : LIST_END;
}

// Links entry e (large set-up `slot`, raster half `record`) into bin b's list with the bin's tiles
// the triangle may cover and those it owns (binTileMasks), and marks the bin touched. False,
// linking nothing, where the triangle misses the bin.
bool linkEntry(uint e, uint slot, LargeTriangle record, ivec2 b) {
  uvec2 tiles = binTileMasks(record, b * int(BIN_SIZE), frame.farPlane);
  if (tiles.x == 0u) return false;
  uint bin = uint(b.y) * control.binsX + uint(b.x);
  largeEntries[e] = LargeEntry(slot, atomicExchange(binData[control.binCount + bin], e), tiles.x, tiles.y);
  touchBin(uvec2(b), 0u);
  return true;
}

// Whether the bin pass (bin_large.comp) links the large triangles into their bins' lists
// (WorkLayout::Gpu) instead of the invocation that set each up.
// The storage-array builds (_k32s: SwiftShader's, gpu_renderer.cpp) always leave the linking to the
// bin pass: SwiftShader compiles the code a specialization constant turns off, and with the linking
// in it the clip pass took its compiler 53 s, against 0.13 s without (docs/DECISIONS.md).
#if defined(PHONGVK_KEYS32) && defined(PHONGVK_STORAGE_ARRAYS)
const bool BIN_PASS = true;
#else
layout(constant_id = SPEC_BIN_PASS) const bool BIN_PASS = false;
#endif

// Stores sub-triangle s's set-up and links it into the list of every bin whose pixels it may
// cover, with the bin's tiles it may cover (binTileMasks); resolve rasterizes it there, in those
// tiles. With BIN_PASS it only writes its entries' owner, for the bin pass to link. False, linking
// nothing, when the set-up records or the bin entries are full.
bool deferToLargePass(TriangleSetup t, EdgeSetup s) {
  ivec4 bins = binsOf(s.bbox);
  uint slot = reserve(1u, control.largeSetupCapacity, false);
  if (slot == LIST_END) return false;
  uint count = uint((bins.z - bins.x + 1) * (bins.w - bins.y + 1));
  uint first = reserve(count, control.largeCapacity, true);
  if (first == LIST_END) return false;
  LargeTriangle record = largeTriangle(t, s);
  largeSetups[slot] = LargeSetup(record, packShading(loadGouraud(t.triangle)));
  if (BIN_PASS) {
    for (uint e = first; e < first + count; ++e) largeEntries[e] = LargeEntry(slot, LIST_END, 0u, first);
    atomicMax(clipList.binGroupsX, min((first + count + BIN_GROUP_SIZE - 1u) / BIN_GROUP_SIZE, control.groupCap));
    return true;
  }
  // Each row of bins from the first to the last that the triangle may reach in it (binRowRange);
  // a bin the triangle misses gets no entry (its reserved one stays unused).
  uint e = first;
  for (int by = bins.y; by <= bins.w; ++by) {
    ivec2 row = binRowRange(record, by, bins);
    for (int bx = row.x; bx <= row.y; ++bx) {
      if (linkEntry(e, slot, record, ivec2(bx, by))) ++e;
    }
  }
  return true;
}

// A sub-triangle with 64-bit edges: deferred to resolve when large, else drawn here. A large one
// is never drawn here: one invocation looping over all its pixels could pass lavapipe's loop budget
// (bindings.glsl checkLoopBudget; a screen-filling triangle did, at row 123 of 480). Without room
// for it, the host grows the lists and renders the frame again (STATUS_LARGE_OVERFLOW). True where
// it drew a fragment that may still win (offerKey); a deferred one is resolve's, never kept.
bool drawOrDefer(TriangleSetup t, EdgeSetup s) {
  if (uint(boxPixels(s.bbox)) > SMALL_TRIANGLE_MAX_PIXELS) {
    if (!IDS_PASS && !deferToLargePass(t, s)) atomicOr(status.flags, STATUS_LARGE_OVERFLOW);
    return false;
  }
  if (!IDS_PASS) markBins(s.bbox);
  return rasterizeRows(t, s);
}
