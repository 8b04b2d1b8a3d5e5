// shared.h — the one header included by both the GLSL compute shaders and the C++ host/reference.
// It defines every buffer struct, binding number, workgroup size and constant that both sides must
// agree on. On the C++ side, static_asserts turn a layout slip into a compile error.
//
// Layout rule: std430. A vec3 is 16-byte aligned and followed by a scalar to fill the slot.
#ifndef PHONGVK_SHARED_H
#define PHONGVK_SHARED_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace phongvk::gpu {
using uint = uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
#define PHONGVK_CONST inline constexpr
#else
#define PHONGVK_CONST const
#extension GL_EXT_shader_8bit_storage : require
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

// ---- Raster constants ----
PHONGVK_CONST uint SUBPIXEL_BITS = 8;        // 1/256 pixel, as Vulkan/D3D hardware
PHONGVK_CONST int SUBPIXEL_ONE = 256;
PHONGVK_CONST int SUBPIXEL_HALF = 128;       // pixel centres sit at (x + 0.5, y + 0.5)
// Guard band: clip polygons whose projection leaves |x|,|y| <= GUARD_BAND pixels around the
// principal point, so snapped coordinates stay below 2^28 subpixels and edge functions in int64.
PHONGVK_CONST float GUARD_BAND = 524288.0f;  // 2^19 pixels
// A triangle whose pixel bounding box has more than this many pixels is not rasterized by its
// own invocation: its set-up is stored and linked into the list of every bin it overlaps, and
// resolve rasterizes it there, tile by tile, keeping the smallest key in registers (no atomics).
// Small triangles stay one invocation each, with atomicMin on the key buffer. 256 since session 5
// (was 1024): with the shading constants stored per set-up, a 2x2 grid of spheres of ~200-pixel
// triangles renders 10% faster in resolve than one invocation each; 128 measured the same as 256.
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
// Dispatches are capped at the smallest maxComputeWorkGroupCount[0] Vulkan allows; the shaders
// loop (grid-stride) when there is more work than that many groups. On a CPU device (lavapipe)
// every workgroup costs about 0.6 us of scheduling however little it does, so there the cap is
// CPU_DISPATCH_GROUPS: a few groups per core, each looping over many items.
PHONGVK_CONST uint MAX_DISPATCH_GROUPS = 65535;
PHONGVK_CONST uint CPU_DISPATCH_GROUPS = 256;
// Clipping a triangle against the near plane and four guard planes yields at most 8 vertices.
PHONGVK_CONST uint MAX_CLIP_VERTICES = 8;

// Specialization constant ids. shade_vertices: the light count, whether any material has a
// specular term, whether every attenuation is constant (b = c = 0). resolve: the interpolation.
PHONGVK_CONST uint SPEC_LIGHT_COUNT = 0;
PHONGVK_CONST uint SPEC_SPECULAR = 1;
PHONGVK_CONST uint SPEC_CONSTANT_ATTENUATION = 2;
PHONGVK_CONST uint SPEC_INTERPOLATION = 0;
// resolve: tiles a workgroup takes at once (local_size_y; 8 lanes each): 1 on CPU devices, 8 on GPUs.
PHONGVK_CONST uint SPEC_RESOLVE_TILES = 1;
// resolve: where the colours go (RESOLVE_OUTPUT_*, from FrameData.keepKeys). A constant, not a
// frame field: lavapipe runs every side of a branch, and the stores of a frame-chosen output each
// cost a loop over the lanes per pixel.
PHONGVK_CONST uint SPEC_RESOLVE_OUTPUT = 2;
// clip pass: whether the bin pass links the large triangles (raster_loops.glsl BIN_PASS).
PHONGVK_CONST uint SPEC_BIN_PASS = 9;
// probe_float.comp: results per probe (native a / b, sqrt, fma; the quotient and root corrected) and group size.
PHONGVK_CONST uint FLOAT_PROBE_RESULTS = 5;
PHONGVK_CONST uint FLOAT_PROBE_GROUP_SIZE = 64;
// The colour into the pixel's key slot, read from there by the host (colorsInKeys) or packed into
// the colour buffer by pack_colors.comp.
PHONGVK_CONST uint RESOLVE_OUTPUT_KEY_SLOTS = 0;
PHONGVK_CONST uint RESOLVE_OUTPUT_KEEP_KEYS = 2;   // keepKeys: into the colour buffer, the final key kept

// Interpolation modes (FrameData.interpolation).
PHONGVK_CONST uint INTERP_PERSPECTIVE = 0;
PHONGVK_CONST uint INTERP_SCREEN = 1;

// Object flags.
PHONGVK_CONST uint OBJECT_CULL_BACK = 1;     // closed surface: back faces are never visible

// ---- Descriptor bindings (one set) ----
PHONGVK_CONST uint BINDING_FRAME = 0;        // FrameData (uniform)
PHONGVK_CONST uint BINDING_VERTICES = 1;     // VertexIn[]
PHONGVK_CONST uint BINDING_TRIANGLES = 2;    // RGBA32UI texels (3 vertex indices, w = object index)
PHONGVK_CONST uint BINDING_OBJECTS = 3;      // ObjectData[]
PHONGVK_CONST uint BINDING_MATERIALS = 4;    // MaterialData[]
PHONGVK_CONST uint BINDING_LIGHTS = 5;       // LightData[]
PHONGVK_CONST uint BINDING_SHADED = 6;       // ShadedVertex.hpos per vertex (vec4[])
PHONGVK_CONST uint BINDING_KEYS = 7;         // uint64 depth|triangle keys, one per pixel
PHONGVK_CONST uint BINDING_COLOR = 8;        // RGB bytes, the image's layout (3 per pixel, row-major)
PHONGVK_CONST uint BINDING_LARGE = 9;        // LargeList header + LargeEntry bin entries
PHONGVK_CONST uint BINDING_BINS = 10;        // BinList header, flags and list heads per bin, touched bins
PHONGVK_CONST uint BINDING_LARGE_SETUPS = 11; // LargeSetup (raster.h) of each large triangle
PHONGVK_CONST uint BINDING_CLIP_LIST = 12;   // IdList header + ids of triangles for the clip pass (clipped or not small)
// The shaded vertices again, as uniform texel buffers (one texel per vertex: hpos; colour) for the
// passes that only read them. Triangles are a texel buffer too: texelFetch is gathered in SIMD by
// CPU devices (lavapipe), where a storage-buffer load is a loop over the lanes. Positions and
// colours are arrays of their own: the triangle pass reads only positions (16 bytes a vertex
// instead of 32 in its cache lines), and each array stays within maxStorageBufferRange for twice
// the vertices (lavapipe: 128 MiB, 8.4M vertices).
PHONGVK_CONST uint BINDING_SHADED_TEXELS = 13;
PHONGVK_CONST uint BINDING_LARGE_TEXELS = 14;        // the large list (BINDING_LARGE), for resolve
PHONGVK_CONST uint BINDING_LARGE_SETUP_TEXELS = 15;  // the large set-ups (BINDING_LARGE_SETUPS), likewise
PHONGVK_CONST uint BINDING_SHADED_COLORS = 16;       // ShadedVertex.color per vertex (vec4[])
PHONGVK_CONST uint BINDING_SHADED_COLOR_TEXELS = 17; // the same, as texels
PHONGVK_CONST uint BINDING_STATUS = 18;              // FrameStatus, host visible: why a frame must be rendered again

// FrameStatus.flags. STATUS_LARGE_OVERFLOW: a large triangle found no room in the set-up records
// or bin entries (the host grows them). STATUS_LOOP_LIMIT: a pass ran out of the loop iterations
// the device allows one invocation (bindings.glsl checkLoopBudget; the host launches more
// workgroups, each taking fewer items). Either way the host renders the frame again.
PHONGVK_CONST uint STATUS_LARGE_OVERFLOW = 1;
PHONGVK_CONST uint STATUS_LOOP_LIMIT = 2;
// Iterations of the loop-budget probe (FrameData.loopProbe; a frame value, so no compiler unrolls it).
PHONGVK_CONST uint LOOP_PROBE_ITERATIONS = 2;

// ---- Buffer structs ----
// A mesh vertex in its object's local frame (position relative to the object origin).
struct VertexIn {
  vec3 position;
  uint object;
  vec3 normal;
  uint pad0;
};

// Output of the per-vertex pass: homogeneous pixel-space position and unclamped Phong colour.
// hpos = (focal * x_view, -focal * y_view, z_view, unused): the screen position is
// principal point + hpos.xy / hpos.z, with y pointing down.
struct ShadedVertex {
  vec4 hpos;
  vec4 color;
};

// Offsets computed in double on the host, so far-away objects keep float precision
// (local + offset instead of world - eye).
struct ObjectData {
  vec3 viewOffset;     // camera-basis coordinates of (origin - eye); per frame
  uint material;
  vec3 lightOffset;    // origin - lighting origin (SceneData::lightingOrigin); fixed per scene
  uint flags;
};

struct MaterialData {
  vec3 color;
  float ka;
  vec3 attenuation;  // a, b, c of 1 / (a + b d + c d^2)
  float kd;
  float ks;
  float n;
  float pad0;
  float pad1;
};

struct LightData {
  vec3 position;     // world coordinates relative to the lighting origin
  float intensity;
  vec3 color;
  float pad0;
};

struct FrameData {
  vec4 right;        // camera basis as rows: view = (dot(right, p), dot(up, p), dot(forward, p))
  vec4 up;
  vec4 forward;
  vec3 ambient;
  float focal;       // pixels per metre at 1 m
  vec3 background;
  float nearPlane;
  vec2 principal;    // (width / 2, height / 2) in pixels
  float farPlane;
  uint lightCount;
  uint width;
  uint height;
  uint interpolation;
  uint triangleCount;
  uint vertexCount;
  uint largeCapacity;  // bin entries the large list can hold
  uint binsX;          // bins per row: ceil(width / BIN_SIZE)
  uint largeSetupCapacity;  // large-triangle set-up records the buffer can hold
  vec3 eye;            // eye - lighting origin, for the view vector
  uint shadeColors;    // 0: colours from the previous frame are still right, only transform
  uint groupCap;       // most workgroups a pass launches; the passes grid-stride beyond it
  uint binCount;       // binsX * bins down
  uint keepKeys;       // 1: resolve leaves each pixel's final key in the key buffer (for diffs)
  uint colorsInKeys;   // 1: resolve writes each colour into its pixel's key slot (raster.h colorSlot), the
                       // host reads and clears it there; 0: into the colour buffer, clearing the key.
                       // The resolve passes take both as SPEC_RESOLVE_OUTPUT.
  uint loopProbe;      // LOOP_PROBE_ITERATIONS
  uint shadePositions; // 0: the shaded positions of the previous frame are still right (same view
                       // and objects); with shadeColors 0 too the host skips the shade pass
  uint pad3;
  uint pad4;
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
  uint groupsX;      // indirect dispatch (min(count, frame.groupCap), 1, 1)
  uint groupsY;      // 1: every dispatch is one row of workgroups (bindings.glsl runtimeOne)
  uint groupsZ;
};

// Header of a list of triangle ids that an indirect dispatch then walks (the clip list).
struct IdList {
  uint count;
  uint groupsX;      // indirect dispatch (min(count / CLIP_GROUP_SIZE rounded up, groupCap), 1, 1)
  uint groupsY;      // 1, as BinList's
  uint groupsZ;
  uint binGroupsX;   // the bin pass's indirect dispatch (WorkLayout::Gpu): the large list's
  uint binGroupsY;   // entries over BIN_GROUP_SIZE, capped at groupCap; (0, 1, 1) without any
  uint binGroupsZ;
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
// the bin's tiles it may cover (bit j * BIN_TILES + i for tile (i, j), raster.h binTileMasks; resolve
// skips the others without reading the set-up) and those of them it owns (covers every pixel centre
// of, never past the far plane). Before the bin pass links an entry, `owned` holds the triangle's
// first entry (bin_large.comp).
struct LargeEntry {
  uint slot;
  uint next;
  uint tiles;
  uint owned;
};

#ifdef __cplusplus
static_assert(sizeof(VertexIn) == 32 && offsetof(VertexIn, normal) == 16);
static_assert(sizeof(ShadedVertex) == 32);
static_assert(sizeof(ObjectData) == 32 && offsetof(ObjectData, lightOffset) == 16);
static_assert(sizeof(MaterialData) == 48 && offsetof(MaterialData, kd) == 28 && offsetof(MaterialData, ks) == 32);
static_assert(sizeof(LightData) == 32 && offsetof(LightData, color) == 16);
static_assert(offsetof(FrameData, ambient) == 48 && offsetof(FrameData, focal) == 60);
static_assert(offsetof(FrameData, background) == 64 && offsetof(FrameData, nearPlane) == 76);
static_assert(offsetof(FrameData, principal) == 80 && offsetof(FrameData, farPlane) == 88);
static_assert(offsetof(FrameData, lightCount) == 92 && offsetof(FrameData, triangleCount) == 108);
static_assert(offsetof(FrameData, vertexCount) == 112 && offsetof(FrameData, eye) == 128);
static_assert(offsetof(FrameData, shadeColors) == 140 && sizeof(FrameData) == 176);
static_assert(sizeof(FrameStatus) == 16);
static_assert(sizeof(LargeList) == 16 && sizeof(LargeEntry) == 16 && sizeof(BinList) == 16 && sizeof(IdList) == 32);
}  // namespace phongvk::gpu
#endif

#endif  // PHONGVK_SHARED_H
