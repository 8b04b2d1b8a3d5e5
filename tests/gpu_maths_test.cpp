// The GPU renderer's own rasterization maths, which the reference does not run, against the
// contract's (edges.h covers, depth.h, gouraud.h): row spans, 32-bit edges for small triangles,
// block classification and tile masks of binned large triangles, their stored shading constants,
// and the colour buffer's RGB words. No device: the shared headers compile as C++ too.
#include "shaders/color_slots.h"
#include "shaders/gouraud.h"
#include "shaders/large_triangles.h"
#include "shaders/row_spans.h"
#include "shaders/small_triangles.h"
#include "shaders/triangle_setup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>
#include <vector>

namespace phongvk {
namespace {

using namespace gpu;

// A 48x40 image's frame: all the spans and tiles below need of it.
FrameData frame() {
  FrameData f{};
  f.width = 48;
  f.height = 40;
  f.principal = vec2(24.0f, 20.0f);
  f.nearPlane = 0.05f;
  f.farPlane = 1000.0f;
  return f;
}

TEST(GpuMaths, RowSpansHoldExactlyTheCoveredPixels) {
  // The GPU loops visit rowSpan(); the reference tests covers() on every box pixel. They must
  // agree on every row of random triangles, slivers and huge ones included.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> coord(-20 * 256, 70 * 256);
  const FrameData f = frame();
  int rows = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    ivec2 v[3];
    for (auto& p : v) p = ivec2(coord(rng), coord(rng));
    if (trial % 3 == 0) v[2] = v[0] + (v[1] - v[0]) * 3 / 2 + ivec2(1, 0);  // sliver
    for (bool front : {false, true}) {
      EdgeSetup s;
      if (!setupEdges(v[0], v[1], v[2], front, f.width, f.height, s)) continue;
      for (int y = s.bbox.y; y <= s.bbox.w; ++y, ++rows) {
        const ivec2 span = rowSpan(s, y);
        for (int x = s.bbox.x; x <= s.bbox.z; ++x) {
          ASSERT_EQ(covers(s, pixelCentre(x, y)), x >= span.x && x <= span.y)
              << "trial " << trial << " pixel " << x << "," << y;
        }
      }
    }
  }
  EXPECT_GT(rows, 10000);
}


TEST(GpuMaths, ThirtyTwoBitCoverageOfSmallTrianglesEqualsTheSixtyFourBitOne) {
  // The GPU's triangle pass rasterizes small triangles with 32-bit edges (setupSmallEdges); they
  // must accept, orient, bound and cover exactly like the 64-bit setup the reference uses, at any
  // position on screen (the image here is large so triangles land far from the origin too).
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> where(-64 * 256, 4000 * 256);
  std::uniform_int_distribution<int> offset(-(SMALL_EXTENT - 1), SMALL_EXTENT - 1);
  const uint width = 3900, height = 3900;
  int rows = 0, covered = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const ivec2 a(where(rng), where(rng));
    const ivec2 b = a + ivec2(offset(rng), offset(rng)) / (trial % 4 + 1);
    const ivec2 c = a + ivec2(offset(rng), offset(rng)) / (trial % 3 + 1);
    if (!fitsSmallEdges(a, b, c)) continue;
    for (bool front : {false, true}) {
      EdgeSetup wide;
      EdgeSetup narrow;
      const bool wideOk = setupEdges(a, b, c, front, width, height, wide);
      ASSERT_EQ(setupSmallEdges(a, b, c, front, width, height, narrow), wideOk) << "trial " << trial;
      if (!wideOk) continue;
      ASSERT_EQ(narrow.bbox, wide.bbox) << "trial " << trial;
      for (int y = wide.bbox.y; y <= wide.bbox.w; ++y, ++rows) {
        for (int x = wide.bbox.x; x <= wide.bbox.z; ++x) {
          covered += covers(wide, pixelCentre(x, y));
          ASSERT_EQ(coversSmall(narrow, x, y), covers(wide, pixelCentre(x, y)))
              << "trial " << trial << " pixel " << x << ", " << y;
        }
      }
    }
  }
  EXPECT_GT(rows, 20000);
  EXPECT_GT(covered, 100000);
}

// Trial `trial`'s random triangle for the block tests, set up in a 1024x1024 image (false: it
// covers nothing there). Its vertices lie around the image, one in four reaching the guard band
// (2^27 subpixels), where the edge functions need all 64 bits.
bool randomBlockTriangle(std::mt19937& rng, int trial, EdgeSetup& s) {
  std::uniform_int_distribution<int> near(-200 * 256, 1200 * 256);
  std::uniform_int_distribution<int> far(-(1 << 27), 1 << 27);
  ivec2 v[3];
  for (int k = 0; k < 3; ++k) v[k] = trial % 4 == k ? ivec2(far(rng), far(rng)) : ivec2(near(rng), near(rng));
  return setupEdges(v[0], v[1], v[2], trial % 2 == 0, 1024, 1024, s);
}

// The edges stepped down column i of a tile from its corner's values e (columnEdges, nextRow)
// decide pixel (i, j) as covers() does (`covered`).
void expectColumnStep(const LargeTriangle& large, const BlockEdges& e, int i, int j, bool covered, int trial) {
  ColumnEdges column = columnEdges(large, e, i);
  for (int row = 0; row < j; ++row) column = nextRow(column);
  ASSERT_EQ(columnCovers(column), covered) << "trial " << trial << " pixel " << i << "," << j;
}

TEST(GpuMaths, BlockClassificationAndSteppedEdgesAgreeWithCovers) {
  // Resolve rasterizes large triangles a block at a time (LargeTriangle): a block called inside
  // must have every pixel covered, one called outside none, and the edge functions stepped from the
  // block's corner, row by row down a column, must decide each pixel exactly as covers() does.
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> blockAt(0, 1000);
  const uint width = 1024, height = 1024;
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 4000; ++trial) {
    EdgeSetup s;
    if (!randomBlockTriangle(rng, trial, s)) continue;
    TriangleSetup t{};
    const LargeTriangle large = largeTriangle(t, s);
    for (int b = 0; b < 8; ++b) {
      const int size = b % 2 ? int(TILE_SIZE) : int(BIN_SIZE);
      // Half the blocks inside the triangle's box, half anywhere in the image.
      const ivec2 origin = b < 4 ? ivec2(std::uniform_int_distribution<int>(s.bbox.x, s.bbox.z)(rng),
                                          std::uniform_int_distribution<int>(s.bbox.y, s.bbox.w)(rng))
                                  : ivec2(blockAt(rng), blockAt(rng));
      const BlockEdges e = blockEdges(large, origin);
      const int block = classifyBlock(large, e, origin, size);
      ++counts[block];
      for (int i = 0; i < size; ++i) {
        for (int j = 0; j < size; ++j) {
          const bool covered = covers(s, pixelCentre(origin.x + i, origin.y + j));
          if (size == int(TILE_SIZE)) expectColumnStep(large, e, i, j, covered, trial);
          const bool inImage = origin.x + i < int(width) && origin.y + j < int(height);
          ASSERT_FALSE(block == BLOCK_INSIDE && !covered) << "trial " << trial;
          ASSERT_FALSE(block == BLOCK_OUTSIDE && inImage && covered) << "trial " << trial;
        }
      }
    }
  }
  // Every kind of block occurs often, so none of the assertions above is vacuous.
  EXPECT_GT(counts[BLOCK_OUTSIDE], 1000);
  EXPECT_GT(counts[BLOCK_PARTIAL], 1000);
  EXPECT_GT(counts[BLOCK_INSIDE], 1000);
}

TEST(GpuMaths, ColumnStepsHoldAtTheGuardBandsReach) {
  // Snapped coordinates lie within 2^27 subpixels of the principal point's (shared.h GUARD_BAND):
  // an edge's dx and dy reach 2^28, where columnEdge's 32-bit s' comes within an eighth of 2^32.
  // Triangles with two corners there and their long edge through a 1024x1024 image, in both
  // windings: every pixel of tiles along that edge as covers() decides it.
  std::mt19937 rng(53);
  const int principal = 512 * 256, reach = 1 << 27;
  std::uniform_int_distribution<int> inward(0, 4000), along(0, 1023 - int(TILE_SIZE)), across(-12, 12);
  int partial = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int sx = trial % 2 ? 1 : -1;  // the long edge rises or falls across the image
    const ivec2 a(principal - reach + inward(rng), principal - sx * (reach - inward(rng)));
    const ivec2 b(principal + reach - inward(rng), principal + sx * (reach - inward(rng)));
    const ivec2 c = trial % 4 < 2 ? ivec2(principal + reach - inward(rng), principal - sx * (reach - inward(rng)))
                                  : ivec2(principal - reach + inward(rng), principal + sx * (reach - inward(rng)));
    EdgeSetup s;
    if (!setupEdges(a, b, c, trial % 3 == 0, 1024, 1024, s)) continue;
    TriangleSetup t{};
    const LargeTriangle large = largeTriangle(t, s);
    for (int k = 0; k < 8; ++k) {
      const int x = along(rng);
      const int y = std::clamp(sx > 0 ? x + across(rng) : 1023 - x + across(rng), 0, 1023 - int(TILE_SIZE));
      const ivec2 origin(x, y);
      const BlockEdges e = blockEdges(large, origin);
      int covered = 0;
      for (int i = 0; i < int(TILE_SIZE); ++i) {
        for (int j = 0; j < int(TILE_SIZE); ++j) {
          const bool inside = covers(s, pixelCentre(origin.x + i, origin.y + j));
          covered += inside;
          expectColumnStep(large, e, i, j, inside, trial);
          if (HasFatalFailure()) return;
        }
      }
      partial += covered > 0 && covered < int(TILE_SIZE * TILE_SIZE);
    }
  }
  EXPECT_GT(partial, 500);  // the long edge crosses most tiles tested (778 with this seed)
}

// Checks binTileMasks for the bin at pixel `bin`: each tile in the first mask exactly when
// classifyBlock does not call it outside, and no tile left out with a covered pixel centre in the
// 1024x1024 image; each in the second (owned) exactly when classifyBlock calls it inside, every
// pixel centre of it covered (none where the triangle reaches past the far plane). Counts the
// tiles kept, left out and owned, and those whose pixels include one on an edge.
void expectBinTileMask(const EdgeSetup& s, ivec2 bin, int counts[5]) {
  TriangleSetup t{};
  t.zMin = 1.0f;
  t.zMax = 2.0f;
  const LargeTriangle large = largeTriangle(t, s);
  const uvec2 masks = binTileMasksExact(large, bin, 2.0f);
  ASSERT_EQ(binTileMasksExact(large, bin, 1.99f), uvec2(masks.x, 0u)) << "owned past the far plane";
  // The estimated masks (the 32-bit key path's) keep every tile the exact ones keep and own none
  // they do not; where they differ is counted.
  const uvec2 estimated = binTileMasksEstimated(large, bin, 2.0f);
  ASSERT_EQ(estimated.x & masks.x, masks.x) << "bin " << bin.x << "," << bin.y;
  ASSERT_EQ(estimated.y & ~masks.y, 0u) << "bin " << bin.x << "," << bin.y;
  ASSERT_EQ(binTileMasksEstimated(large, bin, 1.99f), uvec2(estimated.x, 0u)) << "owned past the far plane";
  counts[4] += std::popcount(estimated.x ^ masks.x) + std::popcount(estimated.y ^ masks.y);
  for (uint tile = 0; tile < BIN_TILES * BIN_TILES; ++tile) {
    const ivec2 origin = bin + ivec2(tile % BIN_TILES, tile / BIN_TILES) * int(TILE_SIZE);
    const bool inMask = (masks.x >> tile & 1u) != 0u;
    const bool owned = (masks.y >> tile & 1u) != 0u;
    const int block = classifyBlock(large, blockEdges(large, origin), origin, int(TILE_SIZE));
    ASSERT_EQ(inMask, block != BLOCK_OUTSIDE) << "bin " << bin.x << "," << bin.y << " tile " << tile;
    ASSERT_EQ(owned, block == BLOCK_INSIDE) << "bin " << bin.x << "," << bin.y << " tile " << tile;
    ++counts[inMask ? 0 : 1];
    counts[3] += owned;
    for (int j = 0; j < int(TILE_SIZE); ++j) {
      for (int i = 0; i < int(TILE_SIZE); ++i) {
        const i64vec2 p = pixelCentre(origin.x + i, origin.y + j);
        const bool inImage = origin.x + i < 1024 && origin.y + j < 1024;
        ASSERT_FALSE(!inMask && inImage && covers(s, p)) << "bin " << bin.x << "," << bin.y << " tile " << tile;
        ASSERT_FALSE(owned && !covers(s, p)) << "bin " << bin.x << "," << bin.y << " tile " << tile;
        const i64vec2 v0(s.v0), v1(s.v1), v2(s.v2);  // setupEdges' origin is (0, 0)
        counts[2] += edgeFunction(v1, v2, p) + s.bias0 == 0 || edgeFunction(v2, v0, p) + s.bias1 == 0 ||
                     edgeFunction(v0, v1, p) + s.bias2 == 0;
      }
    }
  }
}

// rgbWord, which the pack and background passes write the colour buffer with: word w holds bytes
// 4w..4w+3 of the image's RGB bytes (pixel k at 3k, r first), whatever w's phase in the 12-byte
// cycle; the alpha byte is dropped.
TEST(GpuMaths, RgbWordHoldsTheImagesBytes) {
  std::vector<uint32_t> packed;
  for (uint32_t k = 0; k < 13; ++k) packed.push_back(0xA0000000u | (k * 0x030201u + 0x102030u));
  std::vector<uint8_t> bytes;
  for (uint32_t p : packed) bytes.insert(bytes.end(), {uint8_t(p), uint8_t(p >> 8), uint8_t(p >> 16)});
  for (uint32_t w = 0; w < 9; ++w) {
    const uint32_t first = 4 * w / 3;
    uint32_t expected = 0;
    for (uint32_t j = 0; j < 4; ++j) expected |= uint32_t(bytes[4 * w + j]) << (8 * j);
    EXPECT_EQ(rgbWord(w, packed[first], packed[first + 1]), expected) << "word " << w;
  }
}

TEST(GpuMaths, BinTileRectIsTheTilesOfTheRectangle) {
  // Every rectangle of a bin's tiles, against the bits set one tile at a time.
  const int n = int(BIN_TILES);
  for (int x0 = 0; x0 < n; ++x0)
    for (int x1 = x0; x1 < n; ++x1)
      for (int y0 = 0; y0 < n; ++y0)
        for (int y1 = y0; y1 < n; ++y1) {
          uint expected = 0;
          for (int j = y0; j <= y1; ++j)
            for (int i = x0; i <= x1; ++i) expected |= 1u << uint(j * n + i);
          EXPECT_EQ(binTileRect(ivec4(x0, y0, x1, y1)), expected) << x0 << "," << y0 << " - " << x1 << "," << y1;
        }
}

TEST(GpuMaths, BinTileMaskKeepsEveryTileWithACoveredPixel) {
  // The clip pass links a large triangle into a bin with the mask of the bin's tiles it may cover,
  // and resolve rasterizes it only in those. Huge triangles (randomBlockTriangle) in bins under
  // their box and anywhere; and small ones, every bin of their box, with vertices on pixel centres
  // half the time, so that edges pass through pixel centres and tiles' corners (an off-by-one in
  // the mask's comparisons shows there).
  std::mt19937 rng(29);
  std::uniform_int_distribution<int> binAt(0, 1024 / int(BIN_SIZE) - 1);
  std::uniform_int_distribution<int> centre(0, 1023), offset(-60, 60), subpixel(0, 255);
  // Tiles kept, tiles left out, pixel centres on an edge, tiles owned, tiles the estimate decides otherwise.
  int counts[5] = {0, 0, 0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    EdgeSetup s;
    if (trial % 2 == 0) {
      if (!randomBlockTriangle(rng, trial, s)) continue;
      for (int b = 0; b < 4; ++b) {
        const ivec2 pixel = b < 2 ? ivec2(std::uniform_int_distribution<int>(s.bbox.x, s.bbox.z)(rng),
                                          std::uniform_int_distribution<int>(s.bbox.y, s.bbox.w)(rng))
                                  : ivec2(binAt(rng), binAt(rng)) * int(BIN_SIZE);
        expectBinTileMask(s, pixel / int(BIN_SIZE) * int(BIN_SIZE), counts);
      }
      continue;
    }
    const ivec2 c(centre(rng), centre(rng));
    ivec2 v[3];
    for (auto& vertex : v) {
      const int fraction = trial % 4 == 1 ? 128 : subpixel(rng);  // on pixel centres, or anywhere
      vertex = ivec2((c.x + offset(rng)) * 256 + fraction, (c.y + offset(rng)) * 256 + fraction);
    }
    if (!setupEdges(v[0], v[1], v[2], trial % 3 == 0, 1024, 1024, s)) continue;
    for (int by = s.bbox.y / int(BIN_SIZE); by <= s.bbox.w / int(BIN_SIZE); ++by) {
      for (int bx = s.bbox.x / int(BIN_SIZE); bx <= s.bbox.z / int(BIN_SIZE); ++bx) {
        expectBinTileMask(s, ivec2(bx, by) * int(BIN_SIZE), counts);
      }
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(counts[0], 10000);
  EXPECT_GT(counts[1], 10000);
  EXPECT_GT(counts[2], 1000);
  EXPECT_GT(counts[3], 1000);
  // Only tiles an edge passes within a fraction of a subpixel of differ: tiles whose corner pixel
  // centre lies on an edge, which this test makes on purpose (49 of 34,080 kept tiles with this seed).
  EXPECT_LT(counts[4], counts[0] / 100) << counts[4] << " of " << counts[0];
}

// Whether the triangle covers a pixel centre of the 32x32 bin at `bin` inside the 1024x1024 image.
bool binHasCoveredCentre(const EdgeSetup& s, ivec2 bin) {
  for (int y = bin.y; y < std::min(bin.y + int(BIN_SIZE), 1024); ++y) {
    for (int x = bin.x; x < std::min(bin.x + int(BIN_SIZE), 1024); ++x) {
      if (covers(s, pixelCentre(x, y))) return true;
    }
  }
  return false;
}

TEST(GpuMaths, BinRowRangeKeepsEveryBinWithACoveredPixel) {
  // The clip pass links a large triangle into the bins of each row of its box from binRowRange's
  // first to its last: every bin with a pixel centre the triangle covers must be among them. Bins
  // that classifyBlock calls outside have none (BlockClassificationAndSteppedEdgesAgreeWithCovers
  // checks that); any other left out is checked pixel by pixel. Huge triangles
  // (randomBlockTriangle), ones of a few bins with vertices on pixel centres half the time (edges
  // through the rows' centres), and ones with vertices where bins begin or end; both windings.
  std::mt19937 rng(31);
  std::uniform_int_distribution<int> centre(0, 1023), offset(-150, 150), subpixel(0, 255), bin(0, 31), side(0, 1);
  long inRange = 0, reached = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    EdgeSetup s;
    if (trial % 3 == 0) {
      if (!randomBlockTriangle(rng, trial, s)) continue;
    } else {
      // Vertices anywhere near a centre, or on the centre of a bin's first or last pixel column
      // and row (where a bin of a row begins or ends), within a subpixel or two.
      const ivec2 c(centre(rng), centre(rng));
      ivec2 v[3];
      for (auto& vertex : v) {
        if (trial % 3 == 1) {
          const ivec2 pixel = ivec2(bin(rng), bin(rng)) * int(BIN_SIZE) + ivec2(side(rng), side(rng)) * (int(BIN_SIZE) - 1);
          vertex = pixel * 256 + 128 + ivec2(offset(rng) % 3, offset(rng) % 3);
          continue;
        }
        const int fraction = trial % 2 == 0 ? 128 : subpixel(rng);
        vertex = ivec2((c.x + offset(rng)) * 256 + fraction, (c.y + offset(rng)) * 256 + fraction);
      }
      if (!setupEdges(v[0], v[1], v[2], trial / 3 % 2 == 0, 1024, 1024, s)) continue;
    }
    TriangleSetup t{};
    const LargeTriangle large = largeTriangle(t, s);
    const ivec4 bins = s.bbox / int(BIN_SIZE);
    for (int by = bins.y; by <= bins.w; ++by) {
      const ivec2 row = binRowRange(large, by, bins);
      ASSERT_TRUE(row.x > row.y || (row.x >= bins.x && row.y <= bins.z)) << "trial " << trial;
      for (int bx = bins.x; bx <= bins.z; ++bx) {
        const ivec2 bin = ivec2(bx, by) * int(BIN_SIZE);
        const bool kept = bx >= row.x && bx <= row.y;
        inRange += kept;
        const bool maybe = classifyBlock(large, blockEdges(large, bin), bin, int(BIN_SIZE)) != BLOCK_OUTSIDE;
        reached += maybe;
        if (kept || !maybe) continue;
        ASSERT_FALSE(binHasCoveredCentre(s, bin)) << "trial " << trial << " bin " << bx << "," << by;
      }
    }
  }
  // The ranges are close to the bins the triangles reach, and not the whole boxes.
  EXPECT_GT(reached, 10000);
  EXPECT_LT(inRange, reached + reached / 4);
}

// Sutherland-Hodgman as the textbook writes it, over a growing list: the polygon clipTriangle must
// make, in the same order, from the same operations.
std::vector<vec3> textbookClip(const vec3 (&h)[3], float nearPlane, uint projection) {
  std::vector<vec3> poly(h, h + 3);
  for (int plane = 0; plane < 5 && !poly.empty(); ++plane) {
    std::vector<vec3> out;
    for (size_t i = 0; i < poly.size(); ++i) {
      const vec3 a = poly[i], b = poly[(i + 1) % poly.size()];
      const float da = clipDistance(a, plane, nearPlane, projection), db = clipDistance(b, plane, nearPlane, projection);
      if (da >= 0.0f) out.push_back(a);
      if ((da >= 0.0f) != (db >= 0.0f)) out.push_back(edgeCrossing(a, b, da, db));
    }
    poly = out;
  }
  if (poly.size() < 3) poly.clear();
  return poly;
}

TEST(GpuMaths, TheClipperMakesSutherlandHodgmansPolygons) {
  // clipTriangle picks its polygons with constant indices (so that lavapipe keeps them in
  // registers); they must be the textbook's bit for bit: random triangles across the near plane,
  // some reaching past the guard band on one side or several, in both projections.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> z(-1.0f, 2.0f), xy(-1.5f, 1.5f), wide(-4.0e6f, 4.0e6f), pick(0.0f, 1.0f);
  int counts[MAX_CLIP_VERTICES + 1] = {};
  for (uint projection : {PROJECTION_PERSPECTIVE, PROJECTION_ORTHOGRAPHIC}) {
    const FrameData f = frame();
    for (int trial = 0; trial < 40000; ++trial) {
      vec3 h[3];
      for (vec3& v : h) {
        v.z = z(rng);
        const bool far = pick(rng) < 0.3f;
        const float scale = projection == PROJECTION_ORTHOGRAPHIC ? 20.0f : 20.0f * std::abs(v.z);
        v.x = far ? wide(rng) : xy(rng) * scale;
        v.y = far && pick(rng) < 0.7f ? wide(rng) : xy(rng) * scale;
      }
      const std::vector<vec3> want = textbookClip(h, f.nearPlane, projection);
      vec3 poly[MAX_CLIP_VERTICES];
      const int count = clipTriangle(h[0], h[1], h[2], f.nearPlane, projection, poly);
      ASSERT_EQ(size_t(count), want.size()) << "trial " << trial;
      for (int i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(std::bit_cast<uint32_t>(want[size_t(i)][c]), std::bit_cast<uint32_t>(poly[i][c])) << "trial " << trial << " vertex " << i;
      }
      ++counts[count];
    }
  }
  EXPECT_GT(counts[0], 1000) << "nothing left";
  for (int n = 3; n <= 7; ++n) EXPECT_GT(counts[n], n < 7 ? 100 : 10) << "polygons of " << n << " vertices";
}

TEST(GpuMaths, LargeShadingKeepsTheColourOfEveryPixelBitForBit) {
  // The clip pass stores a large triangle's Gouraud constants without n and det, which resolve
  // takes from the triangle's plane: every pixel's colour must be the one computed from the
  // triangle itself, in both interpolation modes and both projections, bit for bit. (An
  // orthographic triangle's plane is through its (X, Y, depth) points; its Gouraud constants are
  // those of the points at W = 1.)
  std::mt19937 rng(41);
  std::uniform_real_distribution<float> xy(-3000.0f, 3000.0f), w(0.05f, 50.0f), colour(0.0f, 1.5f);
  std::uniform_real_distribution<float> pixel(-800.0f, 800.0f);
  int compared = 0;
  for (uint projection : {PROJECTION_PERSPECTIVE, PROJECTION_ORTHOGRAPHIC}) {
    for (int trial = 0; trial < 2000; ++trial) {
      ShadedVertex v[3];
      for (ShadedVertex& s : v) {
        const float z = w(rng);
        const float scale = projection == PROJECTION_ORTHOGRAPHIC ? 1.0f : z / 100.0f;
        s.hpos = vec4(xy(rng) * scale, xy(rng) * scale, z, 1.0f);
        s.color = vec4(colour(rng), colour(rng), colour(rng), 1.0f);
      }
      const GouraudTriangle g = gouraudTriangle(v[0], v[1], v[2], projection);
      const TrianglePlane plane = trianglePlane(vec3(v[0].hpos), vec3(v[1].hpos), vec3(v[2].hpos));
      const GouraudTriangle stored = unpackShading(packShading(g), plane, projection);
      for (int k = 0; k < 8; ++k) {
        const vec3 p(pixel(rng), pixel(rng), 1.0f);
        for (uint mode : {INTERP_PERSPECTIVE, INTERP_SCREEN}) {
          const vec3 expected = interpolateColor(g, p, mode), got = interpolateColor(stored, p, mode);
          for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(std::bit_cast<uint32_t>(got[c]), std::bit_cast<uint32_t>(expected[c]))
                << "projection " << projection << " trial " << trial;
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 2 * 2000 * 8 * 2);
}

}  // namespace
}  // namespace phongvk
