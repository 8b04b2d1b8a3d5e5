// shared.h — the one header of layouts included by both the GLSL shaders and the C++ side: the
// arrays both renderers read (the scene flattened: vertices, objects, materials, lights), the
// frame they render, the raster rules' constants, and the table of descriptor bindings and
// specialization-constant ids. On the C++ side, static_asserts turn a layout slip into a compile
// error. What only the GPU renderer needs (its lists, pass control, workgroup sizes) is in
// gpu_layout.h.
//
// Layout rule: std430 (std140 for the uniform FrameData, the same here). A vec3 is 16-byte aligned
// and followed by a scalar to fill the slot.
#ifndef PHONGVK_SHARED_H
#define PHONGVK_SHARED_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
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

// ---- Raster rules (docs/DESIGN.md "Rasterization") ----
PHONGVK_CONST uint SUBPIXEL_BITS = 8;        // 1/256 pixel, as Vulkan/D3D hardware
PHONGVK_CONST int SUBPIXEL_ONE = 256;
PHONGVK_CONST int SUBPIXEL_HALF = 128;       // pixel centres sit at (x + 0.5, y + 0.5)
// Guard band: clip polygons whose projection leaves |x|,|y| <= GUARD_BAND pixels around the
// principal point, so snapped coordinates stay below 2^28 subpixels and edge functions in int64.
PHONGVK_CONST float GUARD_BAND = 524288.0f;  // 2^19 pixels
// Clipping a triangle against the near plane and four guard planes yields at most 8 vertices.
PHONGVK_CONST uint MAX_CLIP_VERTICES = 8;

// Interpolation modes (FrameData.interpolation).
PHONGVK_CONST uint INTERP_PERSPECTIVE = 0;
PHONGVK_CONST uint INTERP_SCREEN = 1;

// Projections (FrameData.projection; docs/DESIGN.md "Camera"). Perspective: the homogeneous
// pixel-space position h = (X, Y, W) has W = z_view, the screen position is principal + (X, Y) / W.
// Orthographic: focalX and focalY are pixels per metre at any depth, the screen position is
// principal + (X, Y) and h.z is the view depth alone (W = 1; edges.h homogeneousW).
PHONGVK_CONST uint PROJECTION_PERSPECTIVE = 0;
PHONGVK_CONST uint PROJECTION_ORTHOGRAPHIC = 1;

// Shading modes (FrameData.shading; docs/DESIGN.md "Shading"): Gouraud (lit per vertex, colours
// interpolated), flat (one colour per triangle, lit at its centroid with its face normal) and Phong
// (lit per pixel, position, normal and colour interpolated).
PHONGVK_CONST uint SHADING_GOURAUD = 0;
PHONGVK_CONST uint SHADING_FLAT = 1;
PHONGVK_CONST uint SHADING_PHONG = 2;
// Specular models (FrameData.specular): the paper's reflection vector, or Blinn's half vector.
PHONGVK_CONST uint SPECULAR_PHONG = 0;
PHONGVK_CONST uint SPECULAR_BLINN = 1;

// Object flags.
PHONGVK_CONST uint OBJECT_CULL_BACK = 1;     // closed surface: back faces are never visible
PHONGVK_CONST uint OBJECT_POSED = 2;         // placed by a pose: its vertices turned on the fly (phong.h posedVertex)

// ---- Descriptor bindings: the one table (one set; every pass sees it, bindings.glsl) ----
// X(name, binding, descriptor type). The host makes its set layouts and descriptor writes from
// this table (vulkan/pipelines.h SHARED_BINDINGS), the shaders declare the same numbers (bindings.glsl).
#define PHONGVK_BINDINGS(X)                                                                            \
  X(BINDING_FRAME, 0, UNIFORM_BUFFER)              /* FrameData */                                    \
  X(BINDING_VERTICES, 1, UNIFORM_TEXEL_BUFFER)     /* VertexIn[] as RGBA32UI texels */                \
  X(BINDING_TRIANGLES, 2, UNIFORM_TEXEL_BUFFER)    /* 3 vertex indices (a quad half: screen_quads.h), w = object */ \
  X(BINDING_OBJECTS, 3, UNIFORM_TEXEL_BUFFER)      /* ObjectData[] */                                 \
  X(BINDING_MATERIALS, 4, UNIFORM_TEXEL_BUFFER)    /* MaterialData[] */                               \
  X(BINDING_LIGHTS, 5, UNIFORM_TEXEL_BUFFER)       /* LightData[] */                                  \
  X(BINDING_SHADED, 6, STORAGE_BUFFER)             /* ShadedVertex.hpos per vertex (vec4[]) */        \
  X(BINDING_KEYS, 7, STORAGE_BUFFER)               /* 64-bit depth|triangle keys, one per pixel */   \
  X(BINDING_COLOR, 8, STORAGE_BUFFER)              /* RGB bytes, the image's layout */                \
  X(BINDING_LARGE, 9, STORAGE_BUFFER)              /* LargeList header + LargeEntry bin entries */    \
  X(BINDING_BINS, 10, STORAGE_BUFFER)              /* BinList header, flags and heads, touched bins */ \
  X(BINDING_LARGE_SETUPS, 11, STORAGE_BUFFER)      /* LargeSetup of each large triangle */            \
  X(BINDING_CLIP_LIST, 12, STORAGE_BUFFER)         /* IdList header + ids for the clip pass */        \
  X(BINDING_SHADED_TEXELS, 13, UNIFORM_TEXEL_BUFFER)       /* BINDING_SHADED, as texels */            \
  X(BINDING_LARGE_TEXELS, 14, UNIFORM_TEXEL_BUFFER)        /* BINDING_LARGE, for resolve */           \
  X(BINDING_LARGE_SETUP_TEXELS, 15, UNIFORM_TEXEL_BUFFER)  /* BINDING_LARGE_SETUPS, likewise */       \
  X(BINDING_SHADED_COLORS, 16, STORAGE_BUFFER)             /* ShadedVertex.color per vertex */        \
  X(BINDING_SHADED_COLOR_TEXELS, 17, UNIFORM_TEXEL_BUFFER) /* the same, as texels */                  \
  X(BINDING_STATUS, 18, STORAGE_BUFFER)            /* FrameStatus: why a frame must be rendered again */ \
  X(BINDING_CONTROL, 19, UNIFORM_BUFFER)           /* PassControl (gpu_layout.h) */              \
  X(BINDING_UVS, 20, UNIFORM_TEXEL_BUFFER)         /* VertexUv per vertex (scenes with textures) */  \
  X(BINDING_TEXTURES, 21, UNIFORM_TEXEL_BUFFER)    /* TextureData per texture */                     \
  X(BINDING_TEXEL_POOL, 22, UNIFORM_TEXEL_BUFFER)  /* every texture's RGBA8 texels, 4 a texel */      \
  X(BINDING_BVH_NODES, 23, UNIFORM_TEXEL_BUFFER)   /* BvhNode[]: the shadow rays' tree */            \
  X(BINDING_SHADOW_TRIANGLES, 24, UNIFORM_TEXEL_BUFFER) /* ShadowTriangle[], in the tree's leaf order */
// Arrays the passes only read are uniform texel buffers: texelFetch is gathered in SIMD by CPU
// devices (lavapipe), where a storage-buffer load is a loop over the lanes. The shaded positions
// and colours are arrays of their own: the triangle pass reads only positions (16 bytes a vertex
// instead of 32 in its cache lines). The shade pass writes them as storage buffers, a binding's
// worth of vertices a dispatch (gpu_layout.h ShadeChunk), so maxStorageBufferRange does not bound
// a scene's vertices (lavapipe: 128 MiB, 8.4M vertices a binding).

// ---- Specialization constants: the one table of ids, each used once ----
// X(name, constant_id). What each selects is said where the shader declares it.
#define PHONGVK_SPEC_CONSTANTS(X)       \
  X(SPEC_LIGHT_COUNT, 0)                \
  X(SPEC_SPECULAR, 1)                   \
  X(SPEC_CONSTANT_ATTENUATION, 2)       \
  X(SPEC_INTERPOLATION, 3)              \
  X(SPEC_RESOLVE_TILES, 4)              \
  X(SPEC_RESOLVE_OUTPUT, 5)             \
  X(SPEC_BIN_PASS, 6)                   \
  X(SPEC_SELFTEST_SLOTS, 7)             \
  X(SPEC_LIST_CHUNK, 8)                 \
  X(SPEC_SHADING, 9)                    \
  X(SPEC_BLINN, 10)                     \
  X(SPEC_CLIP_POLYGONS, 11)             \
  X(SPEC_PROJECTION, 12)                \
  X(SPEC_TEXTURED, 13)                  \
  X(SPEC_KEY_PASS, 14)                  \
  X(SPEC_SHADOWS, 15)                   \
  X(SPEC_QUADS, 16)                     \
  X(SPEC_POINT_PASS, 17)                \
  X(SPEC_KEPT_LIST, 18)

#define PHONGVK_DECLARE_BINDING(name, binding, type) PHONGVK_CONST uint name = binding;
#define PHONGVK_DECLARE_SPEC(name, id) PHONGVK_CONST uint name = id;
PHONGVK_BINDINGS(PHONGVK_DECLARE_BINDING)
PHONGVK_SPEC_CONSTANTS(PHONGVK_DECLARE_SPEC)
#undef PHONGVK_DECLARE_BINDING
#undef PHONGVK_DECLARE_SPEC

// ---- The scene's arrays ----
// A mesh vertex in its object's local frame (position relative to the object origin).
struct VertexIn {
  vec3 position;
  uint object;
  vec3 normal;
  uint color;  // RGBA8, red in the low byte: multiplies the material's colour (phong.h vertexMaterial)
};

PHONGVK_CONST uint VERTEX_WHITE = 0xFFFFFFFFu;  // the colour of a vertex that has none

// Output of the per-vertex pass: homogeneous pixel-space position and unclamped Phong colour.
// hpos = (focalX * x_view, -focalY * y_view, z_view, unused): the screen position is
// principal point + hpos.xy / hpos.z with a perspective camera (principal point + hpos.xy with an
// orthographic one), with y pointing down.
struct ShadedVertex {
  vec4 hpos;
  vec4 color;
};

// Offsets computed in double on the host, so far-away objects keep float precision
// (local + offset instead of world - eye).
// An object placed by a pose (OBJECT_POSED) keeps its mesh in its own coordinates; the pose's
// linear part (rows; w unused) turns its positions and the inverse transpose its normals, per
// vertex, in the passes, so moving it changes these and no vertex.
struct ObjectData {
  vec3 viewOffset;     // camera-basis coordinates of (origin - eye); per frame
  uint material;
  vec3 lightOffset;    // origin - lighting origin (SceneData::lightingOrigin); changes when a posed object moves
  uint flags;
  vec4 linear0;        // the pose's linear part, row by row (OBJECT_POSED)
  vec4 linear1;
  vec4 linear2;
  vec4 normal0;        // its inverse transpose, row by row
  vec4 normal1;
  vec4 normal2;
};
// ObjectData in 16-byte texels (bindings.glsl objectData).
PHONGVK_CONST uint OBJECT_TEXELS = 8;

struct MaterialData {
  vec3 color;
  float ka;
  vec3 attenuation;  // a, b, c of 1 / (a + b d + c d^2)
  float kd;
  float ks;
  float n;
  uint texture;      // TEXTURE_NONE, or the texture that multiplies C (over the mesh's own)
  float pad1;
};

// Textures (docs/DESIGN.md "Textures"). A vertex's texture coordinate and texture: an array of its
// own, bound only for scenes with textures, so VertexIn and the scenes without any are unchanged.
// uv (0, 0) is the image's top-left corner, (1, 1) its bottom-right (glTF's convention).
struct VertexUv {
  vec2 uv;
  uint texture;  // TEXTURE_NONE, or the index of the mesh's texture in the scene's (TextureData[])
  uint pad0;
};

// A texture in the scene's texel pool: its first texel, its size and its wrap modes
// (TEXTURE_WRAP_* for u in the low byte, for v in the next).
struct TextureData {
  uint offset;
  uint width;
  uint height;
  uint wrap;
};

PHONGVK_CONST uint TEXTURE_NONE = 0xFFFFFFFFu;
PHONGVK_CONST uint TEXTURE_WRAP_REPEAT = 0;
PHONGVK_CONST uint TEXTURE_WRAP_CLAMP = 1;     // clamp to edge
PHONGVK_CONST uint TEXTURE_WRAP_MIRROR = 2;    // mirrored repeat
PHONGVK_CONST uint TEXTURE_FILTER_NEAREST = 0;
PHONGVK_CONST uint TEXTURE_FILTER_BILINEAR = 1;
// The largest side of a texture: Vulkan's guaranteed maxImageDimension2D is 4096, desktop devices
// give 16384, and bilinear weights in 8 bits of a texel need side * 256 below 2^24 (texture.h).
PHONGVK_CONST uint TEXTURE_MAX_SIDE = 16384;

// LightData::flags.
PHONGVK_CONST uint LIGHT_SPOT = 1;     // a spot light: its cone (phong.h spotCone)
PHONGVK_CONST uint LIGHT_SHADOWS = 2;  // lights only what its shadow ray reaches (shadow_rays.h)

struct LightData {
  vec3 position;     // a point or spot light: world coordinates relative to the lighting origin;
                     // a directional light: the unit direction toward it
  float intensity;
  vec3 color;
  float directional;  // 1: a directional light (no position, no fall-off), 0: a point or spot light
  vec3 spotAxis;      // a spot light: the unit direction it points (from the light), else 0
  float spotScale;    // a spot light: 1 / max(cos inner - cos outer, 0.001), else 0 (phong.h spotCone)
  float spotOffset;   // a spot light: -cos outer * spotScale
  uint flags;         // LIGHT_*
  float falloff;      // a point or spot light: 0, the material's attenuation; 1, the inverse square (phong.h)
  float range;        // with the inverse square: where glTF's window reaches 0, metres; 0: none
};

// A node of the shadow rays' bounding volume hierarchy (prepare/shadow_bvh.h), in depth-first
// order: an inner node's first child is the next node. Its box holds its triangles' vertices in
// the lighting frame (the positions the shade pass lights).
struct BvhNode {
  vec3 low;
  uint count;   // 0: an inner node; else a leaf of this many triangles
  vec3 high;
  uint index;   // an inner node: its second child; a leaf: its first triangle in ShadowTriangle order
};

// A triangle as shadow rays test it: its vertices in the lighting frame, its id (the index of the
// scene's triangle) and its three vertex indices (a vertex's own triangles never shadow it).
struct ShadowTriangle {
  vec3 a;
  uint id;
  vec3 b;
  uint v0;
  vec3 c;
  uint v1;
  uint v2;
  uint pad0;
  uint pad1;
  uint pad2;
};

// One frame as the scene and its camera define it: built once per frame by makeFrame
// (prepare/scene_data.h) and read the same way by both renderers.
struct FrameData {
  vec4 right;        // camera basis as rows: view = (dot(right, p), dot(up, p), dot(forward, p))
  vec4 up;
  vec4 forward;
  vec3 ambient;
  float focalX;      // pixels per metre at 1 m, across (fx)
  vec3 background;
  float nearPlane;
  vec2 principal;    // where the view axis meets the image, in pixels from its top-left corner
  float farPlane;
  uint width;
  vec3 eye;          // eye - lighting origin, for the view vector
  uint height;
  uint interpolation;
  uint shading;      // SHADING_*
  uint specular;     // SPECULAR_*
  float focalY;      // pixels per metre at 1 m, down (fy)
  uint projection;   // PROJECTION_*; in the shaders, the specialization constant (bindings.glsl)
  uint textureFilter;  // TEXTURE_FILTER_*
  uint quadBase;     // the first record of the triangle array that is a point's or a line's quad half (screen_quads.h)
  float pixelScale;  // pixels of this frame per pixel of the image (the sample grid's side): points' and lines' widths scale by it
};

#ifdef __cplusplus
static_assert(sizeof(VertexIn) == 32 && offsetof(VertexIn, normal) == 16);
static_assert(sizeof(ShadedVertex) == 32);
static_assert(sizeof(ObjectData) == 16 * OBJECT_TEXELS && offsetof(ObjectData, lightOffset) == 16 &&
              offsetof(ObjectData, normal2) == 112);
static_assert(sizeof(MaterialData) == 48 && offsetof(MaterialData, kd) == 28 && offsetof(MaterialData, ks) == 32);
static_assert(offsetof(MaterialData, texture) == 40);
static_assert(sizeof(VertexUv) == 16 && sizeof(TextureData) == 16);
static_assert(sizeof(LightData) == 64 && offsetof(LightData, color) == 16 && offsetof(LightData, spotAxis) == 32 &&
              offsetof(LightData, spotOffset) == 48 && offsetof(LightData, flags) == 52);
static_assert(sizeof(BvhNode) == 32 && offsetof(BvhNode, high) == 16);
static_assert(sizeof(ShadowTriangle) == 64 && offsetof(ShadowTriangle, b) == 16 && offsetof(ShadowTriangle, c) == 32 &&
              offsetof(ShadowTriangle, v2) == 48);
static_assert(offsetof(FrameData, ambient) == 48 && offsetof(FrameData, focalX) == 60);
static_assert(offsetof(FrameData, background) == 64 && offsetof(FrameData, nearPlane) == 76);
static_assert(offsetof(FrameData, principal) == 80 && offsetof(FrameData, farPlane) == 88);
static_assert(offsetof(FrameData, width) == 92 && offsetof(FrameData, eye) == 96);
static_assert(offsetof(FrameData, height) == 108 && offsetof(FrameData, interpolation) == 112);
static_assert(offsetof(FrameData, shading) == 116 && offsetof(FrameData, specular) == 120);
static_assert(offsetof(FrameData, focalY) == 124);
static_assert(offsetof(FrameData, projection) == 128 && offsetof(FrameData, textureFilter) == 132);
static_assert(offsetof(FrameData, quadBase) == 136 && offsetof(FrameData, pixelScale) == 140);
static_assert(sizeof(FrameData) == 144);

// Every binding number and specialization-constant id appears once in its table.
constexpr bool distinctIds(std::initializer_list<uint> ids) {
  for (auto a = ids.begin(); a != ids.end(); ++a) {
    for (auto b = a + 1; b != ids.end(); ++b) {
      if (*a == *b) return false;
    }
  }
  return true;
}
#define PHONGVK_BINDING_ID(name, binding, type) binding,
#define PHONGVK_SPEC_ID(name, id) id,
static_assert(distinctIds({PHONGVK_BINDINGS(PHONGVK_BINDING_ID)}), "a binding number is used twice");
static_assert(distinctIds({PHONGVK_SPEC_CONSTANTS(PHONGVK_SPEC_ID)}), "a specialization-constant id is used twice");
#undef PHONGVK_BINDING_ID
#undef PHONGVK_SPEC_ID
}  // namespace phongvk::gpu
#endif

#endif  // PHONGVK_SHARED_H
