// gpu_layout.h — what only the GPU renderer's passes and its host side share: workgroup sizes,
// the bin and tile grid, the large triangles' lists, the pass-control block and the frame status.
// The reference never includes it. C++ static_asserts keep the two sides' layouts equal.
#ifndef PHONGVK_GPU_LAYOUT_H
#define PHONGVK_GPU_LAYOUT_H

#include "glsl_cpp.h"
#include "shared.h"

#ifdef __cplusplus
namespace phongvk::gpu {
#endif

// ---- Workgroup sizes (threads per group; converted to group counts once, on the host) ----
// 64 threads: a multiple of NVIDIA's 32-wide warps and of lavapipe's 8-wide AVX2 SIMD lanes.
PHONGVK_CONST uint SHADE_GROUP_SIZE = 64;
PHONGVK_CONST uint SETUP_GROUP_SIZE = 64;
PHONGVK_CONST uint CLIP_GROUP_SIZE = 64;
PHONGVK_CONST uint BIN_GROUP_SIZE = 64;
PHONGVK_CONST uint FILL_GROUP_SIZE = 64;
PHONGVK_CONST uint PACK_GROUP_SIZE = 64;  // pack_colors.comp: four pixels an invocation
// The image is cut into 32x32 pixel bins. Resolve takes one touched bin per workgroup and walks
// it as 4x4 tiles of 8x8 pixels (resolve_large.comp, resolve_small.comp): the bin's large
// triangles are loaded once per tile for all its pixels, and a bin nothing touched is skipped whole.
PHONGVK_CONST uint TILE_SIZE = 8;
PHONGVK_CONST uint BIN_SIZE = 32;
PHONGVK_CONST uint BIN_TILES = BIN_SIZE / TILE_SIZE;  // tiles per bin side

// ---- Small and large triangles ----
// A triangle whose pixel bounding box has more than this many pixels is not rasterized by its
// own invocation: its set-up is stored and linked into the list of every bin it overlaps, and
// resolve rasterizes it there, tile by tile, keeping the smallest key in registers (no atomics).
// Small triangles stay one invocation each, with atomicMin on the key buffer. With the shading
// constants stored per set-up, a 2x2 grid of spheres of ~200-pixel triangles resolves faster
// binned than one invocation each (against a threshold of 1024), and 128 measured the same as 256
// (docs/PERFORMANCE.md, "Raster").
PHONGVK_CONST uint SMALL_TRIANGLE_MAX_PIXELS = 256;
// The large triangles' buffers grow with the image, not the triangle count (a large triangle
// covers many pixels, so few fit on screen at once): room for one set-up record (160 bytes) per
// LARGE_SETUP_PIXELS pixels and one bin entry (16 bytes) per LARGE_ENTRY_PIXELS pixels, with the
// minimums below. When a frame needs more, the host doubles them and renders it again
// (STATUS_LARGE_OVERFLOW); they keep that size for the frames after.
PHONGVK_CONST uint LARGE_SETUP_PIXELS = 512;
PHONGVK_CONST uint LARGE_SETUPS_MIN = 256;
PHONGVK_CONST uint LARGE_ENTRY_PIXELS = 64;
PHONGVK_CONST uint LARGE_ENTRIES_MIN = 4096;
PHONGVK_CONST uint LIST_END = 0xFFFFFFFFu;  // the end of a bin's list of large triangles
// Bin flags (bindings.glsl binData): bit 0, listed for resolve; bit BIN_KEYS_SHIFT + t, some key of
// the bin's tile t (row-major, BIN_TILES x BIN_TILES) was written by atomicMin.
PHONGVK_CONST uint BIN_LISTED = 1;
PHONGVK_CONST uint BIN_KEYS_SHIFT = 1;

// ---- Dispatch ----
// Dispatches are capped at the smallest maxComputeWorkGroupCount[0] Vulkan allows; the shaders
// loop (grid-stride) when there is more work than that many groups. On a CPU device (lavapipe)
// every workgroup costs scheduling time however little it does (docs/PERFORMANCE.md), so there the
// cap is CPU_DISPATCH_GROUPS: a few groups per core, each looping over many items.
PHONGVK_CONST uint MAX_DISPATCH_GROUPS = 65535;
PHONGVK_CONST uint CPU_DISPATCH_GROUPS = 256;
// Bins' lists taken a chunk at a time (SPEC_LIST_CHUNK): a bin that thousands of large triangles
// reach (2,000 screen-filling triangles, a 100k-corner polygon cut into a fan) is more work than
// one lavapipe invocation's loop budget even alone in its workgroup, since resolve walks the list
// once per tile. Frames that run out of the budget with the most workgroups are rendered again
// with resolve_large taking at most LIST_CHUNK_FIRST entries of each list per dispatch (about 34
// loop iterations an entry on the CPU layout, within the 65535), in rounds until every list is
// done; each time the budget still runs out, a quarter as many, down to LIST_CHUNK_MIN.
PHONGVK_CONST uint LIST_CHUNK_FIRST = 1024;
PHONGVK_CONST uint LIST_CHUNK_MIN = 16;
// probe_float.comp: results per probe (native a / b, sqrt, fma; the quotient and root corrected) and group size.
PHONGVK_CONST uint FLOAT_PROBE_RESULTS = 5;
PHONGVK_CONST uint FLOAT_PROBE_GROUP_SIZE = 64;

// Where resolve leaves a pixel's colour (SPEC_RESOLVE_OUTPUT): into its key slot (color_slots.h
// colorSlot), read from there by the host or packed into the colour buffer by pack_colors.comp; or,
// in frames that keep their keys (diffs), into the colour buffer, the final key kept.
PHONGVK_CONST uint RESOLVE_OUTPUT_KEY_SLOTS = 0;
PHONGVK_CONST uint RESOLVE_OUTPUT_KEEP_KEYS = 2;

// Which words of the visibility key a triangle or clip dispatch decides (SPEC_KEY_PASS,
// raster_loops.glsl): the whole 64-bit key by 64-bit atomicMin; or, on the 32-bit key path, the depth
// word in one dispatch and then the triangle id among the fragments at that depth.
PHONGVK_CONST uint KEY_PASS_WHOLE = 0;
PHONGVK_CONST uint KEY_PASS_DEPTH = 1;
PHONGVK_CONST uint KEY_PASS_IDS = 2;

// FrameStatus.flags. STATUS_LARGE_OVERFLOW: a large triangle found no room in the set-up records
// or bin entries (the host grows them). STATUS_LOOP_LIMIT: a pass ran out of the loop iterations
// the device allows one invocation (bindings.glsl checkLoopBudget; the host launches more
// workgroups, each taking fewer items). Either way the host renders the frame again.
PHONGVK_CONST uint STATUS_LARGE_OVERFLOW = 1;
PHONGVK_CONST uint STATUS_LOOP_LIMIT = 2;
// Not a failure: resolve_large, taking bins' lists a chunk at a time (SPEC_LIST_CHUNK), left some
// bin's list unfinished; the host runs it again (a round) until no bin is left.
PHONGVK_CONST uint STATUS_MORE_ROUNDS = 4;
// The clip pass met a triangle to clip (one crossing the near plane or the guard band) in a pass
// built without the clipper (SPEC_CLIP_POLYGONS). The host renders the frame again with it.
PHONGVK_CONST uint STATUS_NEEDS_CLIPPING = 8;

// The clip pass's builds (SPEC_CLIP_POLYGONS): without the clipper (a triangle to clip asks for the
// other build), and with the near plane and the guard band's (clip.h clipTriangle, as the reference
// clips). The host picks what a frame's scene box needs (prepare/scene_data.h boxClip).
PHONGVK_CONST uint CLIP_NONE = 0;
PHONGVK_CONST uint CLIP_ALL = 1;
// Iterations of the loop-budget probe (PassControl.loopProbe; a uniform value, so no compiler unrolls it).
PHONGVK_CONST uint LOOP_PROBE_ITERATIONS = 2;

// What the GPU renderer tells its passes beside the frame: work counts, list capacities, the bin
// grid, the workgroup cap and which parts of the shade pass run. Written by the renderer alone
// (compute/gpu_buffers.cpp writeControl), once per attempt at a frame. The shade pass's vertices
// are not here but in its push constants (ShadeChunk), a chunk a dispatch.
struct PassControl {
  uint triangleCount;
  uint largeCapacity;       // bin entries the large list can hold
  uint largeSetupCapacity;  // large-triangle set-up records the buffer can hold
  uint binsX;               // bins per row: ceil(width / BIN_SIZE)
  uint binCount;            // binsX * bins down
  uint groupCap;            // most workgroups a pass launches; the passes grid-stride beyond it
  uint loopProbe;           // LOOP_PROBE_ITERATIONS
  uint shadeColors;         // 0: colours from the previous frame are still right, only transform
  uint shadePositions;      // 0: the shaded positions of the previous frame are still right (same
                            // view and objects); with shadeColors 0 too the shade pass is skipped
  // The records of whole point quads, [pointBase, pointEnd), both halves of each (a share may
  // begin or end inside one): the point pass draws them, a quad an invocation, and the triangle
  // pass the records before and after (raster_triangles.comp). pointBase = pointEnd: none.
  uint pointBase;
  uint pointEnd;
  uint pad2;
};

// The vertices one shade dispatch shades, [first, end), as push constants: shaded position and
// colour i go to slot i - first of the chunk's binding. The shaded arrays are written as storage
// buffers, each binding at most maxStorageBufferRange (lavapipe: 128 MiB, 8.4M vertices), and read
// as texels, whose limit is far larger (2 GiB there): a scene with more vertices is shaded in
// chunks, each dispatch with the bindings at its chunk (compute/gpu_recording.cpp).
struct ShadeChunk {
  uint first;
  uint end;
};

// What went wrong in a frame (STATUS_* flags); the host clears it before each submission.
struct FrameStatus {
  uint flags;
  uint pad0;
  uint pad1;
  uint pad2;
};

// Header of the touched-bin list. The bin buffer holds this header, then per bin its flags
// (BIN_LISTED, BIN_KEYS), then per bin the first entry of its large-triangle list (LIST_END when
// empty), then the touched bins as x | y << 16 in the order they were first touched; resolve is an
// indirect dispatch over those. The host resets flags and heads before each frame.
struct BinList {
  uint count;        // bins touched
  uint groupsX;      // indirect dispatch (min(count, control.groupCap), 1, 1)
  uint groupsY;      // 1: every dispatch is one row of workgroups (bindings.glsl runtimeOne)
  uint groupsZ;
};

// Header of a list of triangle ids that an indirect dispatch then walks (the clip list). Its buffer
// holds the header, room for every triangle's id, and on the 32-bit key path keptWords(triangles)
// words of the triangle pass's kept triangles: bit t % 32 of word t / 32 set where its depth
// dispatch drew a fragment of small triangle t that may still win a pixel (raster_loops.glsl
// keepTriangle); in a scene of fewer than KEPT_LIST_BELOW triangles (keptList) the kept
// triangles' ids instead, listed, room for every triangle's after the words: the triangle pass's
// from the start of that room up, the clip pass's (keepClipped: a clip-listed triangle with a
// fragment that may still win) from its end down. A record is drawn by one of the two passes and
// kept once at most, so both fit. Larger scenes' clip passes keep none (their ids dispatch walks
// the whole clip list).
FN uint keptWords(uint triangles) { return (triangles + 31u) / 32u; }
// Below this many triangles the ids dispatch walks a list of the kept triangles, one an
// invocation (an atomicAdd each in the depth dispatch), rather than their bits a triangle an
// invocation: its SIMD batches then hold kept triangles only (fig6_orbit_red's ids dispatch 1.24 ->
// 0.98 ms). The grids keep the bits: a million triangles' atomics cost more than the list saved.
PHONGVK_CONST uint KEPT_LIST_BELOW = 16384u;
FN bool keptList(uint triangles) { return triangles < KEPT_LIST_BELOW; }
// The kept bits one invocation of an ids pass walks: a word (32) where that leaves at least 8192
// invocations, else the largest power of two that does, down to 1. A word an invocation is what
// spares a grid of a million triangles most of their set-ups; in a scene of a few thousand, 32
// triangles one after another in one invocation took longer than the ids pass had before.
FN uint keptSpan(uint triangles) {
  uint span = 32u;
  while (span > 1u && (triangles + span - 1u) / span < 8192u) span /= 2u;
  return span;
}
FN uint keptChunks(uint triangles) { uint span = keptSpan(triangles); return (triangles + span - 1u) / span; }

struct IdList {
  uint count;
  uint groupsX;      // indirect dispatch (min(count / CLIP_GROUP_SIZE rounded up, groupCap), 1, 1)
  uint groupsY;      // 1, as BinList's
  uint groupsZ;
  uint binGroupsX;   // the bin pass's indirect dispatch (WorkLayout::Gpu): the large list's
  uint binGroupsY;   // entries over BIN_GROUP_SIZE, capped at groupCap; (0, 1, 1) without any
  uint binGroupsZ;
  uint keptListed;   // the 32-bit key path's kept triangles listed (keptList scenes)
  uint idsGroupsX;   // the triangle pass's ids dispatch over them: keptListed over SETUP_GROUP_SIZE,
  uint idsGroupsY;   // capped at groupCap; (0, 1, 1) with none
  uint idsGroupsZ;
  uint keptClipped;      // the clip pass's kept triangles listed (keptList scenes)
  uint clipIdsGroupsX;   // the clip pass's ids dispatch over them: keptClipped over CLIP_GROUP_SIZE,
  uint clipIdsGroupsY;   // capped at groupCap; (0, 1, 1) with none
  uint clipIdsGroupsZ;
  uint pad;
};

// Header of the large triangles' bin entries (LargeEntry), which follow it in the buffer, each
// bin's list threaded through them from its head.
struct LargeList {
  uint count;        // entries reserved (may exceed the capacity: the frame is then rendered again)
  uint setups;       // set-up slots reserved (likewise)
  uint pad0;
  uint pad1;
};

// One large triangle in one bin's list: its set-up slot, the next entry of the bin (LIST_END: none),
// the bin's tiles it may cover (bit j * BIN_TILES + i for tile (i, j), large_triangles.h
// binTileMasks; resolve skips the others without reading the set-up) and those of them it owns
// (covers every pixel centre of, never past the far plane). Before the bin pass links an entry,
// `owned` holds the triangle's first entry (bin_large.comp).
struct LargeEntry {
  uint slot;
  uint next;
  uint tiles;
  uint owned;
};

#ifdef __cplusplus
static_assert(sizeof(PassControl) == 48 && offsetof(PassControl, shadeColors) == 28);
static_assert(sizeof(FrameStatus) == 16 && sizeof(ShadeChunk) == 8);
static_assert(sizeof(LargeList) == 16 && sizeof(LargeEntry) == 16 && sizeof(BinList) == 16 && sizeof(IdList) == 64);

// Where the clip list's buffer keeps the kept words (IdList), their bytes, and its whole size, with
// the kept words (and the kept list, keptList) on the 32-bit key path (`keptBits`) and without
// them elsewhere.
inline uint64_t keptWordsOffset(uint32_t triangles) { return sizeof(IdList) + uint64_t(triangles) * sizeof(uint32_t); }
inline uint64_t keptWordsBytes(uint32_t triangles) { return uint64_t(keptWords(triangles)) * sizeof(uint32_t); }
inline uint64_t clipListBytes(uint32_t triangles, bool keptBits) {
  const uint64_t list = keptList(triangles) ? uint64_t(triangles) * sizeof(uint32_t) : 0u;
  return keptWordsOffset(triangles) + (keptBits ? keptWordsBytes(triangles) + list : 0u);
}
}  // namespace phongvk::gpu
#endif

#endif  // PHONGVK_GPU_LAYOUT_H
