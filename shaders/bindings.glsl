// bindings.glsl — the descriptor set every phongvk pass shares (numbers from shared.h's table).
// Included by every pass (and the graphics baseline's vertex stage); a pass simply ignores the
// buffers it does not use.
//
// Arrays the passes only read are uniform texel buffers of RGBA32UI texels, each shared.h struct
// being whole texels, unpacked by the functions below (uintBitsToFloat keeps every bit, even of
// subnormals and NaNs): lavapipe gathers a texelFetch in SIMD, while it loads from a storage
// buffer lane by lane, with a branch and a bounds check each.
#include "shared.h"
#include "gpu_layout.h"
#include "gouraud.h"
#include "large_triangles.h"
#include "screen_quads.h"

layout(std140, binding = BINDING_FRAME) uniform Frame { FrameData frameBlock; };
// The frame and the pass control as the passes read them: private copies every main makes first
// (loadUniforms). Where FrameData went to a function by value straight from the block, lavapipe
// loaded the members it used lane by lane, a gather with a bounds check each, in every pixel loop
// (resolve_large on fig1_cube: 33 such gathers, a fifth of its instructions); the copy is loaded once.
FrameData frame;
// The camera's projection (shared.h PROJECTION_*), which loadUniforms writes over the copy's
// field: a constant, so a perspective pass compiles to the code it had before orthographic
// cameras existed (the shared maths asks frame.projection in every pixel's depth).
layout(constant_id = SPEC_PROJECTION) const uint PROJECTION = PROJECTION_PERSPECTIVE;
// The scene has points or lines (screen_quads.h): the records from frame.quadBase on are their quads'
// halves. Without any, no quad code at all (on lavapipe code a pass merely contains costs every triangle).
layout(constant_id = SPEC_QUADS) const bool QUADS = false;

#ifdef PHONGVK_GRAPHICS_STAGE
void loadUniforms() {
  frame = frameBlock;
  frame.projection = PROJECTION;
}
#else
layout(std140, binding = BINDING_CONTROL) uniform Control { PassControl controlBlock; };
PassControl control;

// 1, read from a value no compiler knows: every dispatch of ours is one row of workgroups (the
// host's vkCmdDispatch(x, 1, 1), and groupsY = 1 in the lists that indirect dispatches read).
uint runtimeOne() { return gl_NumWorkGroups.y; }

// lavapipe (Mesa 22.3) replaces up to four uniform values that decide a branch or the end of a loop
// by their current values and, if that halves the shader, compiles the result again every time the
// pipeline is bound, keeping every copy: relit frames paid for the shade pass's recompilation, and
// the process gained code mappings frame after frame (docs/DECISIONS.md, "Uniform inlining"). So
// the control fields that decide branches and loop ends are multiplied by runtimeOne(), which the
// inliner cannot look into.
void loadUniforms() {
  frame = frameBlock;
  frame.projection = PROJECTION;
  control = controlBlock;
  uint one = runtimeOne();
  control.triangleCount *= one;
  control.shadeColors *= one;
  control.shadePositions *= one;
  control.loopProbe *= one;
  control.pointBase *= one;
  control.pointEnd *= one;
}
#endif
// The arrays the passes only read, as RGBA32UI texels. The 32-bit key path's builds for devices with
// small texel-buffer limits (PHONGVK_STORAGE_ARRAYS: SwiftShader's is 65,536 texels, a 33,000-vertex
// mesh) read them from storage buffers instead (vulkan/context.h storageArrays).
#ifdef PHONGVK_STORAGE_ARRAYS
#define TEXELS(b, name) layout(std430, binding = b) readonly buffer name##Block { uvec4 name[]; };
#define TEXEL(name, i) name[i]
#else
#define TEXELS(b, name) layout(binding = b) uniform usamplerBuffer name;
#define TEXEL(name, i) texelFetch(name, int(i))
#endif
TEXELS(BINDING_VERTICES, vertexTexels)
TEXELS(BINDING_TRIANGLES, triangleTexels)
TEXELS(BINDING_OBJECTS, objectTexels)
TEXELS(BINDING_MATERIALS, materialTexels)
TEXELS(BINDING_LIGHTS, lightTexels)
TEXELS(BINDING_SHADED_TEXELS, shadedTexels)             // shadedPositions[], after the shade pass
TEXELS(BINDING_SHADED_COLOR_TEXELS, shadedColorTexels)  // shadedColors[], likewise
TEXELS(BINDING_LARGE_TEXELS, largeTexels)               // large list, after the raster passes
TEXELS(BINDING_LARGE_SETUP_TEXELS, largeSetupTexels)    // largeSetups[], likewise
TEXELS(BINDING_UVS, uvTexels)                           // VertexUv[] (scenes with textures)
TEXELS(BINDING_TEXTURES, textureTexels)                 // TextureData[]
TEXELS(BINDING_TEXEL_POOL, texelPool)                   // RGBA8 texels, four a texel
TEXELS(BINDING_BVH_NODES, bvhTexels)                    // BvhNode[] (scenes with shadowed lights)
TEXELS(BINDING_SHADOW_TRIANGLES, shadowTriangleTexels)  // ShadowTriangle[], likewise
layout(std430, binding = BINDING_SHADED) writeonly buffer ShadedPositions { vec4 shadedPositions[]; };
layout(std430, binding = BINDING_SHADED_COLORS) writeonly buffer ShadedColors { vec4 shadedColors[]; };
// The key buffer: a 64-bit key per pixel (depth.h), or on the 32-bit key path the same key as its
// two words, low (the triangle id) first: the same bytes either way. A pair, not two uints: one
// 8-byte load or store a pixel, where lavapipe makes a loop over the lanes of each (the atomics
// take the pair's words: raster_loops.glsl offerKey).
#ifdef PHONGVK_KEYS32
layout(std430, binding = BINDING_KEYS) buffer Keys { uvec2 keyPairs[]; };
uvec2 loadKey(uint i) { return keyPairs[i]; }
void storeKey(uint i, uvec2 key) { keyPairs[i] = key; }
#else
layout(std430, binding = BINDING_KEYS) buffer Keys { uint64_t keys[]; };
uint64_t loadKey(uint i) { return keys[i]; }
void storeKey(uint i, uint64_t key) { keys[i] = key; }
#endif
// The colour buffer's byte b (RGB bytes, the image's layout) set to `value`. On the 32-bit key path
// (no 8-bit storage) through its word, with atomics: the word's other bytes are other pixels',
// which other lanes may be writing.
#ifdef PHONGVK_KEYS32
layout(std430, binding = BINDING_COLOR) buffer ColorByteWords { uint colorByteWords[]; };
void storeColorByte(uint b, uint value) {
  uint shift = 8u * (b & 3u);
  atomicAnd(colorByteWords[b >> 2], ~(0xFFu << shift));
  atomicOr(colorByteWords[b >> 2], value << shift);
}
#else
layout(std430, binding = BINDING_COLOR) writeonly buffer Colors { uint8_t colorBytes[]; };
void storeColorByte(uint b, uint value) { colorBytes[b] = uint8_t(value); }
#endif
layout(std430, binding = BINDING_LARGE) buffer Large { LargeList large; LargeEntry largeEntries[]; };
// Bins (shared.h BinList): binData[b] is bin b's flags, binData[binCount + b] the head of its
// large-triangle list, binData[2 binCount + k] the k-th touched bin as x | y << 16. Resolve visits
// only those, resetting the keys it read, so a frame never clears or scans the whole key buffer.
layout(std430, binding = BINDING_BINS) buffer Bins { BinList binList; uint binData[]; };
layout(std430, binding = BINDING_LARGE_SETUPS) writeonly buffer LargeSetups { LargeSetup largeSetups[]; };
layout(std430, binding = BINDING_CLIP_LIST) buffer ClipList { IdList clipList; uint clipIds[]; };
layout(std430, binding = BINDING_STATUS) buffer Status { FrameStatus status; };

#ifndef PHONGVK_GRAPHICS_STAGE
// Every pass calls this last. lavapipe (llvmpipe) allows one invocation 65535 loop iterations in
// all (each back edge of every loop counts: LP_MAX_TGSI_LOOP_ITERATIONS) and then silently leaves
// every loop, so a pass given too much work would end early and the image be wrong. A loop of
// control.loopProbe iterations that runs fewer shows the budget ran out: the host is told
// (STATUS_LOOP_LIMIT) and renders the frame again with more workgroups.
void checkLoopBudget() {
  uint n = 0u;
  for (uint i = 0u; i < control.loopProbe; ++i) ++n;
  if (n != control.loopProbe) atomicOr(status.flags, STATUS_LOOP_LIMIT);
}
#endif

// A texel's four words as floats, bit for bit.
vec4 floats(uvec4 t) { return uintBitsToFloat(t); }

VertexIn vertexIn(uint i) {
  uvec4 a = TEXEL(vertexTexels, 2u * i);
  uvec4 b = TEXEL(vertexTexels, 2u * i + 1u);
  return VertexIn(floats(a).xyz, a.w, floats(b).xyz, b.w);
}

ObjectData objectData(uint i) {
  uvec4 a = TEXEL(objectTexels, OBJECT_TEXELS * i);
  uvec4 b = TEXEL(objectTexels, OBJECT_TEXELS * i + 1u);
  ObjectData o = ObjectData(floats(a).xyz, a.w, floats(b).xyz, b.w, vec4(0.0f), vec4(0.0f), vec4(0.0f), vec4(0.0f),
                            vec4(0.0f), vec4(0.0f));
  if ((b.w & OBJECT_POSED) == 0u) return o;  // the pose is read only where there is one
  o.linear0 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 2u));
  o.linear1 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 3u));
  o.linear2 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 4u));
  o.normal0 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 5u));
  o.normal1 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 6u));
  o.normal2 = floats(TEXEL(objectTexels, OBJECT_TEXELS * i + 7u));
  return o;
}

MaterialData materialData(uint i) {
  vec4 a = floats(TEXEL(materialTexels, 3u * i));
  vec4 b = floats(TEXEL(materialTexels, 3u * i + 1u));
  vec4 c = floats(TEXEL(materialTexels, 3u * i + 2u));
  return MaterialData(a.xyz, a.w, b.xyz, b.w, c.x, c.y, floatBitsToUint(c.z), c.w);
}

LightData lightData(uint i) {
  vec4 a = floats(TEXEL(lightTexels, 4u * i));
  vec4 b = floats(TEXEL(lightTexels, 4u * i + 1u));
  vec4 c = floats(TEXEL(lightTexels, 4u * i + 2u));
  uvec4 d = TEXEL(lightTexels, 4u * i + 3u);
  return LightData(a.xyz, a.w, b.xyz, b.w, c.xyz, c.w, uintBitsToFloat(d.x), d.y, uintBitsToFloat(d.z), uintBitsToFloat(d.w));
}

// The shadow rays' tree and triangles (shadow_rays.h; `scene` stands for the reference's arrays).
BvhNode bvhNode(uint scene, uint i) {
  uvec4 a = TEXEL(bvhTexels, 2u * i);
  uvec4 b = TEXEL(bvhTexels, 2u * i + 1u);
  return BvhNode(floats(a).xyz, a.w, floats(b).xyz, b.w);
}

ShadowTriangle shadowTriangle(uint scene, uint i) {
  uvec4 a = TEXEL(shadowTriangleTexels, 4u * i);
  uvec4 b = TEXEL(shadowTriangleTexels, 4u * i + 1u);
  uvec4 c = TEXEL(shadowTriangleTexels, 4u * i + 2u);
  uvec4 d = TEXEL(shadowTriangleTexels, 4u * i + 3u);
  return ShadowTriangle(floats(a).xyz, a.w, floats(b).xyz, b.w, floats(c).xyz, c.w, d.x, d.y, d.z, d.w);
}

VertexUv vertexUv(uint i) {
  uvec4 t = TEXEL(uvTexels, i);
  return VertexUv(uintBitsToFloat(t.xy), t.z, t.w);
}

TextureData textureData(uint i) {
  uvec4 t = TEXEL(textureTexels, i);
  return TextureData(t.x, t.y, t.z, t.w);
}

// Texel i of the pool (RGBA8), the (i mod 4)-th word of its texel (selects, not a dynamic index).
uint poolTexel(uint i) {
  uvec4 q = TEXEL(texelPool, i >> 2u);
  uint k = i & 3u;
  return k == 0u ? q.x : (k == 1u ? q.y : (k == 2u ? q.z : q.w));
}

// Bin entry e of the large list: one texel after the 16-byte header.
LargeEntry largeEntry(uint e) {
  uvec4 t = TEXEL(largeTexels, 1u + e);
  return LargeEntry(t.x, t.y, t.z, t.w);
}

// Large set-up `slot` (large_triangles.h LargeSetup, ten texels): its raster half, the first five.
LargeTriangle largeSetup(uint slot) {
  int k = int(10u * slot);
  uvec4 a = TEXEL(largeSetupTexels, k);
  uvec4 b = TEXEL(largeSetupTexels, k + 1);
  uvec4 c = TEXEL(largeSetupTexels, k + 2);
  uvec4 d = TEXEL(largeSetupTexels, k + 3);
  uvec4 f = TEXEL(largeSetupTexels, k + 4);
  return LargeTriangle(ivec4(a), TrianglePlane(uintBitsToFloat(b.xyz), uintBitsToFloat(b.w)), ivec2(c.xy), ivec2(c.zw),
                       ivec2(d.xy), int(d.z), int(d.w), int(f.x), uintBitsToFloat(f.y), uintBitsToFloat(f.z), f.w);
}

// Large set-up `slot`'s shading half (large_triangles.h LargeShading), the last five texels; the fifth (W)
// only for interpolation `mode` INTERP_SCREEN (a specialization constant: no read otherwise).
LargeShading largeShading(uint slot, uint mode) {
  int k = int(10u * slot) + 5;
  vec4 w = mode == INTERP_SCREEN ? floats(TEXEL(largeSetupTexels, k + 4)) : vec4(0.0f);
  return LargeShading(floats(TEXEL(largeSetupTexels, k)), floats(TEXEL(largeSetupTexels, k + 1)),
                      floats(TEXEL(largeSetupTexels, k + 2)), floats(TEXEL(largeSetupTexels, k + 3)), w);
}

// Whether record `id` of the triangle array is a point's or a line's quad half.
bool isQuad(uint id) { return QUADS && id >= frame.quadBase; }

// The vertices whose attributes record `id`'s three corners take (screen_quads.h recordVertices).
uvec3 cornerVertices(uint id, uvec4 record) { return recordVertices(record, isQuad(id)); }

// The homogeneous corners of record `id`: a triangle's vertices, a quad half's corners.
void recordCorners(uint id, uvec4 record, out vec3 h0, out vec3 h1, out vec3 h2) {
  uvec3 v = cornerVertices(id, record);  // a quad's code is no vertex: never read as one
  h0 = floats(TEXEL(shadedTexels, v.x)).xyz;
  h1 = floats(TEXEL(shadedTexels, v.y)).xyz;
  h2 = floats(TEXEL(shadedTexels, v.z)).xyz;
  if (isQuad(id)) quadCorners(h0, h1, record.z, frame, h0, h1, h2);
}

// The three shaded vertices of record `id`: for a quad half, its corners with its ends' colours.
void loadTriangle(uint id, out ShadedVertex a, out ShadedVertex b, out ShadedVertex c) {
  uvec4 t = TEXEL(triangleTexels, id);
  uvec3 v = cornerVertices(id, t);
  a.color = floats(TEXEL(shadedColorTexels, v.x));
  b.color = floats(TEXEL(shadedColorTexels, v.y));
  c.color = floats(TEXEL(shadedColorTexels, v.z));
  vec3 h0, h1, h2;
  recordCorners(id, t, h0, h1, h2);
  a.hpos = vec4(h0, 1.0f);
  b.hpos = vec4(h1, 1.0f);
  c.hpos = vec4(h2, 1.0f);
}

// Record `id`'s homogeneous corners and whether its back face is culled (a quad's never is).
void loadForSetup(uint id, out vec3 h0, out vec3 h1, out vec3 h2, out bool cullBack) {
  uvec4 tri = TEXEL(triangleTexels, id);
  cullBack = !isQuad(id) && (TEXEL(objectTexels, OBJECT_TEXELS * tri.w + 1u).w & OBJECT_CULL_BACK) != 0u;  // ObjectData.flags
  recordCorners(id, tri, h0, h1, h2);
}

// Triangle `id`'s Gouraud constants (gouraud.h).
GouraudTriangle loadGouraud(uint id) {
  ShadedVertex a, b, c;
  loadTriangle(id, a, b, c);
  return gouraudTriangle(a, b, c, frame.projection);
}
