// First resolve pass: the touched bins with large triangles (resolve.glsl). A workgroup takes one
// 32x32 bin at a time, 8x8 tile by tile; each lane owns the 8 pixels of one column of a tile,
// 8 lanes a tile (one SIMD batch on a CPU device, so everything per tile is uniform there; a GPU
// workgroup takes several tiles at once, SPEC_RESOLVE_TILES). Per pixel: its key from the key
// buffer (where small triangles went by atomicMin, only in tiles they touched), then the bin's
// large triangles that may cover the tile (LargeEntry.tiles, set by the clip pass; the others are
// walked past in a loop, nextEntryIn, so only those that reach the tile take a trip of the
// rasterizing loop; lavapipe would run both sides of a branch), each tested at the lane's 8
// pixels (edge values stepped down the column). Where one offers a smaller key, the key and its
// Gouraud colour (from the constants the clip pass stored with the set-up, LargeShading) are kept
// in registers. Then where a large triangle won: the colour stored by resolve.glsl storeColor;
// where a small one wins, the key stays for resolve_small. On a CPU device, a tile that one large
// triangle owns (covers every pixel centre of, short of the far plane; LargeEntry.owned) with
// nothing else reaching it is only shaded (shadeOwnedTile): that saves the depth tests and edge
// steps of the tiles one triangle owns, most of a floor's tiles (docs/PERFORMANCE.md, "Resolve").
//
// The entries that miss the tile are skipped (without the masks most (tile, entry) pairs would be
// misses), and each entry's rows are shaded from its own constants instead of the winner's being
// read per row (5 gathers a row): only entries that reach a tile cost it (docs/PERFORMANCE.md).
//
// The keys build (resolve_large_keys.comp; the code is resolve_large.glsl) leaves every winner's
// key for the second resolve pass, for frames lit per pixel (flat and Phong shading) and lists
// taken in rounds: a list too long for lavapipe's loop budget (LIST_CHUNK, resolve.glsl) is taken
// a chunk of entries per dispatch: every tile of the bin against the chunk's entries, the smallest keys kept
// in the key buffer between rounds (no colours, no owned tiles), and the bin's head moved past the
// chunk; STATUS_MORE_ROUNDS asks the host for another round while some list is not done.
//
// The 8 rows are spelled out by the FOR_ROWS macro instead of indexing per-lane arrays, which
// lavapipe may keep in memory.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "resolve_large.glsl"
