// large_triangles.h — the GPU renderer's large triangles, binned and rasterized by resolve a block
// of pixels at a time: the stored set-up (LargeSetup), the tiles of a bin a triangle may cover or
// owns, and edge values stepped across a block. Not part of the contract: the keys and colours
// are the reference's (edges.h covers, depth.h planeKey, gouraud.h), which the tests check pixel
// by pixel.
#ifndef PHONGVK_LARGE_TRIANGLES_H
#define PHONGVK_LARGE_TRIANGLES_H

#include "glsl_cpp.h"
#include "shared.h"
#include "gpu_layout.h"
#include "edges.h"
#include "depth.h"
#include "gouraud.h"
#include "triangle_setup.h"

SHARED_BEGIN

// What resolve needs of a large sub-triangle, set up once by the triangle or clip pass (std430,
// 80 bytes): its oriented vertices and edge biases (EdgeSetup in 32 bits: snapped coordinates
// stay below 2^28), box, plane, depth range and id.
struct LargeTriangle {
  ivec4 bbox;
  TrianglePlane plane;
  ivec2 v0;
  ivec2 v1;
  ivec2 v2;
  int bias0;
  int bias1;
  int bias2;
  float zMin;
  float zMax;
  uint triangle;
};

FN LargeTriangle largeTriangle(TriangleSetup t, EdgeSetup s) {
  LargeTriangle l;
  l.bbox = s.bbox;
  l.plane = t.plane;
  l.v0 = s.origin + s.v0;  // snapped coordinates again (setupEdges' origin is 0)
  l.v1 = s.origin + s.v1;
  l.v2 = s.origin + s.v2;
  l.bias0 = s.bias0;
  l.bias1 = s.bias1;
  l.bias2 = s.bias2;
  l.zMin = t.zMin;
  l.zMax = t.zMax;
  l.triangle = t.triangle;
  return l;
}

// The three edge functions (plus biases) at the centre of pixel `origin`, the first of a block.
struct BlockEdges {
  EdgeInt e0;
  EdgeInt e1;
  EdgeInt e2;
};

FN BlockEdges blockEdges(LargeTriangle t, ivec2 origin) {
  ivec2 p = pixelCentre(origin.x, origin.y);
  BlockEdges e;
  e.e0 = edgeAdd(edgeAt(t.v1, t.v2, p), edgeInt(t.bias0));
  e.e1 = edgeAdd(edgeAt(t.v2, t.v0, p), edgeInt(t.bias1));
  e.e2 = edgeAdd(edgeAt(t.v0, t.v1, p), edgeInt(t.bias2));
  return e;
}

// Edge a -> b's function at pixel origin + (i, j), from its value e there: one pixel right adds
// 256 (a.y - b.y), one down 256 (b.x - a.x). Exact, so it equals edgeFunction at that centre.
FN EdgeInt edgeStep(ivec2 a, ivec2 b, EdgeInt e, int i, int j) {
  return edgeAdd(edgeAdd(e, edgePixels(a.y - b.y, i)), edgePixels(b.x - a.x, j));
}

// How a block relates to a large triangle's pixel centres: none covered, some may be, all covered.
PHONGVK_CONST int BLOCK_OUTSIDE = 0;
PHONGVK_CONST int BLOCK_PARTIAL = 1;
PHONGVK_CONST int BLOCK_INSIDE = 2;

// One edge over the size x size block at pixel `origin`: the function is affine, so its extremes
// are at the corner pixels, reached by stepping from e.
FN int classifyEdge(ivec2 a, ivec2 b, EdgeInt e, int size) {
  EdgeInt zero = edgeInt(0);
  EdgeInt right = edgeStep(a, b, zero, size - 1, 0);
  EdgeInt down = edgeStep(a, b, zero, 0, size - 1);
  EdgeInt lo = edgeAdd(edgeAdd(e, edgeMin(right, zero)), edgeMin(down, zero));
  EdgeInt hi = edgeAdd(edgeAdd(e, edgeMax(right, zero)), edgeMax(down, zero));
  if (edgeNegative(hi)) return BLOCK_OUTSIDE;
  return !edgeNegative(lo) ? BLOCK_INSIDE : BLOCK_PARTIAL;
}

// Whether the size x size block at pixel `origin` overlaps the triangle's box.
FN bool blockInBox(LargeTriangle t, ivec2 origin, int size) {
  return origin.x <= t.bbox.z && origin.x + size - 1 >= t.bbox.x && origin.y <= t.bbox.w && origin.y + size - 1 >= t.bbox.y;
}

// BLOCK_INSIDE: covers() holds at every pixel centre of the size x size block at `origin` (which
// may reach past the image); BLOCK_OUTSIDE: at none (within the image); else test each pixel.
FN int classifyBlock(LargeTriangle t, BlockEdges e, ivec2 origin, int size) {
  if (!blockInBox(t, origin, size)) return BLOCK_OUTSIDE;
  int c0 = classifyEdge(t.v1, t.v2, e.e0, size);
  int c1 = classifyEdge(t.v2, t.v0, e.e1, size);
  int c2 = classifyEdge(t.v0, t.v1, e.e2, size);
  return min(c0, min(c1, c2));
}

// One edge's function across a bin in float: its value at the bin's first pixel centre (exact,
// then estimated), what one pixel right and one down add, and a bound on how far any value of the
// bin computed from them (classifyEdgeEstimate) may stray from the exact one. The bound holds for any
// faithful rounding (an error under one unit in the last place per operation, with or without
// fused multiply-adds: SwiftShader does not promise round-to-nearest): edgeEstimate is within
// 2^9 + 2^-22 |e|, each of classifyEdgeEstimate's few operations within 2^-23 of the largest magnitude
// involved, M = |e| + BIN_SIZE (|dx| + |dy|); the margin, 1024 + M / 65536, is several times that.
// Values stay integers below 2^63 or zero: no denormal, overflow or NaN.
struct EdgeEstimate {
  float at;
  float dx;
  float dy;
  float margin;
};

FN EdgeEstimate edgeEstimateOf(ivec2 a, ivec2 b, EdgeInt e) {
  EdgeEstimate r;
  r.at = edgeEstimate(e);
  r.dx = float(a.y - b.y) * float(SUBPIXEL_ONE);
  r.dy = float(b.x - a.x) * float(SUBPIXEL_ONE);
  r.margin = (abs(r.at) + float(BIN_SIZE) * (abs(r.dx) + abs(r.dy))) * (1.0f / 65536.0f) + 1024.0f;
  return r;
}

// How a block of the bin relates to one edge, from its estimate: `base` the edge's estimate at
// the block's first pixel centre, `corner` the block's size less one pixel. BLOCK_OUTSIDE only where
// the largest value at its pixel centres is negative beyond the margin, BLOCK_INSIDE only where the
// smallest is at least the margin, else BLOCK_PARTIAL. So it never calls a block outside or inside
// that classifyEdge would not, and differs from it only within the margin of 0.
FN int classifyEstimate(EdgeEstimate e, float base, float corner) {
  float hi = base + max(e.dx * corner, 0.0f) + max(e.dy * corner, 0.0f);
  float lo = base + min(e.dx * corner, 0.0f) + min(e.dy * corner, 0.0f);
  if (hi + e.margin < 0.0f) return BLOCK_OUTSIDE;
  return lo - e.margin >= 0.0f ? BLOCK_INSIDE : BLOCK_PARTIAL;
}

// Tile (i, j) of the bin against one edge (classifyEstimate).
FN int classifyEdgeEstimate(EdgeEstimate e, int i, int j) {
  float base = e.at + e.dx * float(i * int(TILE_SIZE)) + e.dy * float(j * int(TILE_SIZE));
  return classifyEstimate(e, base, float(TILE_SIZE - 1u));
}

// The whole bin against the three edges (classifyEstimate), the least of the three.
FN int classifyBinEstimate(EdgeEstimate e0, EdgeEstimate e1, EdgeEstimate e2) {
  float corner = float(BIN_SIZE - 1u);
  return min(classifyEstimate(e0, e0.at, corner), min(classifyEstimate(e1, e1.at, corner), classifyEstimate(e2, e2.at, corner)));
}

// The bin's tiles x0..x1 of rows y0..y1, r = (x0, y0, x1, y1) in tiles within the bin (x0 <= x1,
// y0 <= y1, all below BIN_TILES): bit j * BIN_TILES + i for tile (i, j). One row's bits times a
// bit at the start of each of the rows (no carries: a row's bits stay within its BIN_TILES).
FN uint binTileRect(ivec4 r) {
  uint row = ((2u << uint(r.z)) - 1u) & ~((1u << uint(r.x)) - 1u);
  uint rowStarts = ((1u << (BIN_TILES * BIN_TILES)) - 1u) / ((1u << BIN_TILES) - 1u);  // bit 0 of every row
  uint rows = ((2u << (uint(r.w) * BIN_TILES)) - 1u) & ~((1u << (uint(r.y) * BIN_TILES)) - 1u);
  return row * (rowStarts & rows);
}

// The tiles of the bin at pixel `origin` that hold pixels of the triangle's box (as blockInBox
// picks them; the bin overlaps the box).
FN uint binTilesInBox(LargeTriangle t, ivec2 origin) {
  return binTileRect(clamp(t.bbox - ivec4(origin, origin), 0, int(BIN_SIZE) - 1) / int(TILE_SIZE));
}

// Tile `tile`'s bit in a bin's masks (binTileMasksExact): kept unless `block` is BLOCK_OUTSIDE,
// owned where it is BLOCK_INSIDE.
FN void addTile(INOUT(uvec2) masks, int tile, int block) {
  uint bit = 1u << uint(tile);
  if (block != BLOCK_OUTSIDE) masks.x |= bit;
  if (block == BLOCK_INSIDE) masks.y |= bit;
}

// The tiles of the bin at pixel `origin` where the triangle may cover a pixel centre (x): bit
// j * BIN_TILES + i for tile (i, j) unless classifyBlock calls it outside, 0 for none; and those
// it owns (y): every pixel centre of the tile covered (BLOCK_INSIDE) and no depth of the triangle
// past the far plane, so wherever nothing else reaches such a tile the triangle wins each of its
// pixels without a depth test (resolve_large.comp). Both forms unrolled: lavapipe counts every loop
// iteration against one invocation's budget (bindings.glsl checkLoopBudget), and 16 of them per
// bin of a triangle across a 4K image's 8160 bins pass it (a loop on the 32-bit key path: glsl_cpp.h
// UNROLL_KEYS64; a frame that runs out of the budget is rendered again with more workgroups).
FN uvec2 binTileMasksExact(LargeTriangle t, ivec2 origin, float farPlane) {
  BlockEdges e = blockEdges(t, origin);
  uvec2 masks = uvec2(0u);
  UNROLL_KEYS64 for (int j = 0; j < int(BIN_TILES); ++j) {
    UNROLL_KEYS64 for (int i = 0; i < int(BIN_TILES); ++i) {
      ivec2 step = ivec2(i, j) * int(TILE_SIZE);
      BlockEdges tile;
      tile.e0 = edgeStep(t.v1, t.v2, e.e0, step.x, step.y);
      tile.e1 = edgeStep(t.v2, t.v0, e.e1, step.x, step.y);
      tile.e2 = edgeStep(t.v0, t.v1, e.e2, step.x, step.y);
      addTile(masks, j * int(BIN_TILES) + i, classifyBlock(t, tile, origin + step, int(TILE_SIZE)));
    }
  }
  if (!(t.zMax <= farPlane)) masks.y = 0u;
  return masks;
}

// binTileMasksExact's masks from the edges' float estimates (classifyEdgeEstimate): every tile
// the exact masks keep is kept, and every tile owned here the exact masks own; a tile within the
// margin of an edge may be kept or left unowned where the exact masks would not, which costs
// resolve a tile's pixel tests and changes no pixel. The 32-bit key path's masks: with the edge
// values in pairs of words, the exact tile steps cost several times the float ones (docs/DECISIONS.md,
// "The 32-bit key path"). The whole bin is classified first (classifyBinEstimate, which keeps the
// same promises: the margin bounds every value of the bin): a bin outside an edge keeps no tile, one
// inside all three keeps and owns the tiles of the box, and only a bin an edge crosses tests its
// tiles. The tile loop's trip count says which, not a branch: lavapipe runs both sides of a branch,
// but leaves a loop no lane enters after one masked trip (docs/PERFORMANCE.md, "Raster").
FN uvec2 binTileMasksEstimated(LargeTriangle t, ivec2 origin, float farPlane) {
  BlockEdges e = blockEdges(t, origin);
  EdgeEstimate e0 = edgeEstimateOf(t.v1, t.v2, e.e0);
  EdgeEstimate e1 = edgeEstimateOf(t.v2, t.v0, e.e1);
  EdgeEstimate e2 = edgeEstimateOf(t.v0, t.v1, e.e2);
  int whole = classifyBinEstimate(e0, e1, e2);
  uint inBox = whole == BLOCK_INSIDE ? binTilesInBox(t, origin) : 0u;
  uvec2 masks = uvec2(inBox, inBox);
  int rows = whole == BLOCK_PARTIAL ? int(BIN_TILES) : 0;  // else the bin's tiles are all alike
  DONT_UNROLL for (int j = 0; j < rows; ++j) {
    UNROLL_KEYS64 for (int i = 0; i < int(BIN_TILES); ++i) {
      int block = blockInBox(t, origin + ivec2(i, j) * int(TILE_SIZE), int(TILE_SIZE)) ? BLOCK_INSIDE : BLOCK_OUTSIDE;
      block = min(block, min(classifyEdgeEstimate(e0, i, j), min(classifyEdgeEstimate(e1, i, j), classifyEdgeEstimate(e2, i, j))));
      addTile(masks, j * int(BIN_TILES) + i, block);
    }
  }
  if (!(t.zMax <= farPlane)) masks.y = 0u;
  return masks;
}

#ifdef PHONGVK_KEYS32
FN uvec2 binTileMasks(LargeTriangle t, ivec2 origin, float farPlane) { return binTileMasksEstimated(t, origin, farPlane); }
#else
FN uvec2 binTileMasks(LargeTriangle t, ivec2 origin, float farPlane) { return binTileMasksExact(t, origin, farPlane); }
#endif

// x on edge a -> b at height y (subpixels), to within a subpixel (the quotient is truncated);
// a.y != b.y, and y between them. The product stays within 64 bits for snapped coordinates.
FN int edgeXAt(ivec2 a, ivec2 b, int y) { return a.x + edgeQuotient(edgeProduct(b.x - a.x, y - a.y), b.y - a.y); }

// `range` (lowest and highest x, subpixels) widened to the part of edge a -> b between heights y0
// and y1, if any of it lies there.
FN ivec2 widenByEdge(ivec2 a, ivec2 b, int y0, int y1, ivec2 range) {
  int lo = max(min(a.y, b.y), y0);
  int hi = min(max(a.y, b.y), y1);
  if (lo > hi) return range;
  int x0 = a.y == b.y ? a.x : edgeXAt(a, b, lo);
  int x1 = a.y == b.y ? b.x : edgeXAt(a, b, hi);
  return ivec2(min(range.x, min(x0, x1)), max(range.y, max(x0, x1)));
}

// The bins of bin row `by` (first and last column, within `bins`, the bins of the triangle's box;
// first > last when none) that can hold a pixel centre the large triangle covers: those under the
// part of the triangle between the row's first and last pixel centres in its box. That part is
// convex, so its x extremes are where its edges enter and leave those heights, or its vertices
// between them; one subpixel either side covers edgeXAt's truncation. The pixel columns whose
// centres lie in that range, within the box (rounded as pixelBounds rounds), give the bins. A
// superset of the bins with a covered pixel centre, as binTileMasks' tiles are of the tiles with
// one, found per row of bins instead of by testing every bin of the box (a thin wedge of a ground
// disc has ~3x as many bins in its box as it reaches).
FN ivec2 binRowRange(LargeTriangle t, int by, ivec4 bins) {
  int y0 = max(by * int(BIN_SIZE), t.bbox.y) * SUBPIXEL_ONE + SUBPIXEL_HALF;
  int y1 = min(by * int(BIN_SIZE) + int(BIN_SIZE) - 1, t.bbox.w) * SUBPIXEL_ONE + SUBPIXEL_HALF;
  ivec2 x = ivec2(2147483647, -2147483647);
  x = widenByEdge(t.v0, t.v1, y0, y1, x);
  x = widenByEdge(t.v1, t.v2, y0, y1, x);
  x = widenByEdge(t.v2, t.v0, y0, y1, x);
  int first = max(floorDiv256(x.x - 1 - SUBPIXEL_HALF + 255), t.bbox.x);
  int last = min(floorDiv256(x.y + 1 - SUBPIXEL_HALF), t.bbox.z);
  if (x.x > x.y || first > last) return ivec2(bins.z + 1, bins.z);
  return ivec2(first, last) / int(BIN_SIZE);
}

// One edge down column i of a tile (TILE_SIZE pixels square) in 32-bit words, exactly. With e the
// edge function (plus bias) at the tile's first pixel centre, dy = a.y - b.y and dx = b.x - a.x,
// pixel (i, j) of the tile has e + 256 s, s = i dy + j dx, and is covered where that is >= 0, that
// is where s >= ceil(-e / 256), s being an integer. s less its smallest value in the tile,
// s' = s - 7 (min(dy, 0) + min(dx, 0)), lies in [0, 7 (|dx| + |dy|)]: below 2^32, because the guard
// band keeps every snapped coordinate within 2^27 subpixels of the principal point's (shared.h
// GUARD_BAND), so |dx|, |dy| <= 2^28 and 7 (|dx| + |dy|) <= 0.875 * 2^32. So s' is a uint, stepped
// down the column by adding dx modulo 2^32 (exact, as every true value lies in the uint's range),
// and the pixel is covered where s' >= least = ceil(-e / 256) - 7 (min(dy, 0) + min(dx, 0)) held to
// [0, 2^32 - 1] (0: the whole column is covered; 2^32 - 1: none of it is, s' never reaching it).
// Only `least` needs the edge's 64-bit value, once per tile; the rows need one 32-bit add and
// compare per edge, where 64-bit values (emulated in two words on the 32-bit key path) need several.
struct ColumnEdge {
  uint at;     // s' at the current row
  uint down;   // dx: what one row down adds, modulo 2^32
  uint least;  // covered where at >= least
};

FN ColumnEdge columnEdge(ivec2 a, ivec2 b, EdgeInt e, int i) {
  int dy = a.y - b.y;
  int dx = b.x - a.x;
  int last = int(TILE_SIZE) - 1;
  ColumnEdge c;
  c.at = uint((dy < 0 ? last - i : i) * abs(dy)) + uint(last * max(-dx, 0));  // each term < 2^31
  c.down = uint(dx);
  EdgeInt lowest = edgeAdd(edgeInt(last * min(dy, 0)), edgeInt(last * min(dx, 0)));  // 7 min(...), in 64 bits
  c.least = edgeClampToUint(edgeSub(edgeSub(edgeInt(0), edgeFloorDiv256(e)), lowest));
  return c;
}

// The three edges down column i of a tile (columnEdge), from their values at its first pixel (e).
struct ColumnEdges {
  ColumnEdge e0;
  ColumnEdge e1;
  ColumnEdge e2;
};

FN ColumnEdges columnEdges(LargeTriangle t, BlockEdges e, int i) {
  ColumnEdges c;
  c.e0 = columnEdge(t.v1, t.v2, e.e0, i);
  c.e1 = columnEdge(t.v2, t.v0, e.e1, i);
  c.e2 = columnEdge(t.v0, t.v1, e.e2, i);
  return c;
}

FN bool columnCovers(ColumnEdges c) { return c.e0.at >= c.e0.least && c.e1.at >= c.e1.least && c.e2.at >= c.e2.least; }

FN ColumnEdges nextRow(ColumnEdges c) {
  c.e0.at += c.e0.down;
  c.e1.at += c.e1.down;
  c.e2.at += c.e2.down;
  return c;
}

// A large triangle's GouraudTriangle as resolve reads it for each tile the triangle may cover:
// stored with its set-up by the clip pass (LargeSetup) instead of the triangle's index, its three
// vertices' positions and colours and the products above. n and det are the triangle plane's n
// and h0n (trianglePlane: the same products of the same positions), so they are not stored; and
// since perspective-correct interpolation reads only t0..t3, resolve reads t4 (W) only for
// screen-space interpolation.
struct LargeShading {
  vec4 t0;  // u1, c0.x
  vec4 t1;  // u2, c0.y
  vec4 t2;  // dc1, c0.z
  vec4 t3;  // dc2, 0
  vec4 t4;  // w1, w2, 0, 0
};

FN LargeShading packShading(GouraudTriangle g) {
  LargeShading s;
  s.t0 = vec4(g.u1, g.c0.x);
  s.t1 = vec4(g.u2, g.c0.y);
  s.t2 = vec4(g.dc1, g.c0.z);
  s.t3 = vec4(g.dc2, 0.0f);
  s.t4 = vec4(g.w1, g.w2, 0.0f, 0.0f);
  return s;
}

// The GouraudTriangle that packShading(g) kept, with n and det from g's triangle's plane: every
// field equals g's, bit for bit (t4 may be left zero in perspective mode, which does not read W).
// With n shared, the dot product of the pixel ray and n is the same value in depthAt and in
// interpolateColor, computed once per pixel. With an orthographic camera g's n is (0, 0, n.z) and
// det n.z (gouraudTriangle), n.z being the same products of the same positions as the plane's.
FN GouraudTriangle unpackShading(LargeShading s, TrianglePlane plane, uint projection) {
  GouraudTriangle g;
  g.u1 = vec3(s.t0);
  g.u2 = vec3(s.t1);
  g.c0 = vec3(s.t0.w, s.t1.w, s.t2.w);
  g.n = plane.n;
  g.det = plane.h0n;
  if (projection == PROJECTION_ORTHOGRAPHIC) {
    g.n = vec3(0.0f, 0.0f, plane.n.z);
    g.det = plane.n.z;
  }
  g.w1 = s.t4.x;
  g.w2 = s.t4.y;
  g.dc1 = vec3(s.t2);
  g.dc2 = vec3(s.t3);
  return g;
}

// bin-entry loop reads both halves for each tile the triangle may cover (LargeEntry.tiles).
struct LargeSetup {
  LargeTriangle raster;
  LargeShading shading;
};

SHARED_END

#ifdef __cplusplus
static_assert(sizeof(phongvk::gpu::LargeSetup) == 160 && offsetof(phongvk::gpu::LargeSetup, shading) == 80);
static_assert(sizeof(phongvk::gpu::LargeTriangle) == 80 && offsetof(phongvk::gpu::LargeTriangle, v0) == 32);
static_assert(offsetof(phongvk::gpu::LargeTriangle, zMin) == 68 && offsetof(phongvk::gpu::LargeTriangle, triangle) == 76);
static_assert(offsetof(phongvk::gpu::LargeTriangle, bias0) == 56 && offsetof(phongvk::gpu::LargeTriangle, bias2) == 64);
#endif

#endif  // PHONGVK_LARGE_TRIANGLES_H
