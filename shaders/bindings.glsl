// bindings.glsl — the descriptor set every phongvk pass shares (numbers from shared.h).
// Included by the .comp files after shared.h; a pass simply ignores the buffers it does not use.
layout(std140, binding = BINDING_FRAME) uniform Frame { FrameData frame; };
layout(std430, binding = BINDING_VERTICES) readonly buffer Vertices { VertexIn vertices[]; };
layout(std430, binding = BINDING_OBJECTS) readonly buffer Objects { ObjectData objects[]; };
layout(std430, binding = BINDING_MATERIALS) readonly buffer Materials { MaterialData materials[]; };
layout(std430, binding = BINDING_LIGHTS) readonly buffer Lights { LightData lights[]; };
layout(std430, binding = BINDING_SHADED) buffer Shaded { ShadedVertex shaded[]; };
layout(std430, binding = BINDING_KEYS) buffer Keys { uint64_t keys[]; };
layout(std430, binding = BINDING_COLOR) writeonly buffer Colors { uint colors[]; };
layout(std430, binding = BINDING_LARGE) buffer Large { LargeList large; uvec2 largeEntries[]; };
// Bins (shared.h BinList): binData[b] is bin b's flags, binData[binCount + b] the head of its
// large-triangle list, binData[2 binCount + k] the k-th touched bin as x | y << 16. Resolve visits
// only those, resetting the keys it read, so a frame never clears or scans the whole key buffer.
layout(std430, binding = BINDING_BINS) buffer Bins { BinList binList; uint binData[]; };
layout(std430, binding = BINDING_LARGE_SETUPS) buffer LargeSetups { LargeTriangle largeSetups[]; };
layout(std430, binding = BINDING_CLIP_LIST) buffer ClipList { IdList clipList; uint clipIds[]; };

layout(binding = BINDING_TRIANGLES) uniform usamplerBuffer triangleTexels;
layout(binding = BINDING_SHADED_TEXELS) uniform samplerBuffer shadedTexels;

// Shaded vertex v, read through the texel view (for passes after shade_vertices).
ShadedVertex shadedVertex(uint v) {
  return ShadedVertex(texelFetch(shadedTexels, int(2u * v)), texelFetch(shadedTexels, int(2u * v + 1u)));
}

// The three shaded vertices of triangle `id`.
void loadTriangle(uint id, out ShadedVertex a, out ShadedVertex b, out ShadedVertex c) {
  uvec4 t = texelFetch(triangleTexels, int(id));
  a = shadedVertex(t.x);
  b = shadedVertex(t.y);
  c = shadedVertex(t.z);
}

// Triangle `id`'s homogeneous vertices and whether its back face is culled.
void loadForSetup(uint id, out vec3 h0, out vec3 h1, out vec3 h2, out bool cullBack) {
  uvec4 tri = texelFetch(triangleTexels, int(id));
  cullBack = (objects[tri.w].flags & OBJECT_CULL_BACK) != 0u;
  h0 = texelFetch(shadedTexels, int(2u * tri.x)).xyz;
  h1 = texelFetch(shadedTexels, int(2u * tri.y)).xyz;
  h2 = texelFetch(shadedTexels, int(2u * tri.z)).xyz;
}
