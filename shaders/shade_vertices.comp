// Per-vertex pass: transform to homogeneous pixel space and evaluate Phong (phong.h).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "phong.h"
#include "bindings.glsl"
#include "shadow_rays.h"

layout(local_size_x = SHADE_GROUP_SIZE) in;

// Specialized to the scene (see shared.h): the light loop unrolls, unused terms compile away.
layout(constant_id = SPEC_LIGHT_COUNT) const uint LIGHT_COUNT = 0u;
layout(constant_id = SPEC_SPECULAR) const bool SPECULAR = true;
layout(constant_id = SPEC_CONSTANT_ATTENUATION) const bool CONSTANT_ATTENUATION = false;
layout(constant_id = SPEC_BLINN) const bool BLINN = false;  // Blinn's half vector (render.specular)
// Flat and Phong shading light pixels, not vertices (resolve_small.comp): only the positions here.
layout(constant_id = SPEC_SHADING) const uint SHADING = SHADING_GOURAUD;
// Some light casts shadows (docs/DESIGN.md "Shadows"): those lights reach a vertex only along an
// unblocked ray; without any, no ray code at all.
layout(constant_id = SPEC_SHADOWS) const bool SHADOWS = false;

layout(push_constant) uniform ShadeChunkBlock { ShadeChunk chunk; };

// Vertex i, its shaded position and colour stored at `slot` of the chunk's bindings.
void shadeVertex(uint i, uint slot) {
  VertexIn stored = vertexIn(i);
  ObjectData object = objectData(stored.object);
  VertexIn v = posedVertex(stored, object);
  MaterialData m = vertexMaterial(materialData(object.material), v.color);
  // Only when the view or an object moved: a loop of 0 or 1 trips, the same for every lane (on
  // lavapipe no cheaper than an if: a loop body runs once, masked, even when no lane enters it).
  [[dont_unroll]] for (uint k = control.shadePositions; k != 0u; --k) {
    shadedPositions[slot] = vec4(toHomogeneous(v.position, object.viewOffset, frame), 1.0f);
  }
  if (control.shadeColors == 0u || SHADING != SHADING_GOURAUD) return;  // unchanged, or lit per pixel
  vec3 P = lightingPosition(v.position, object.lightOffset);
  vec3 V = viewVector(P, frame);
  vec3 color = phongAmbient(m, frame.ambient);
  for (uint l = 0u; l < LIGHT_COUNT; ++l) {
    LightData light = lightData(l);
    vec3 lit = phongLightWith(P, v.normal, V, m, light, SPECULAR, CONSTANT_ATTENUATION, BLINN);
    if (SHADOWS) lit = shadowedTerm(0u, light, lit, P, vertexOwners(i));
    color += lit;
  }
  // A point's or a line's vertex without a normal is unlit (only scenes with them have such vertices).
  if (QUADS && isUnlit(v.normal)) color = m.color;
  shadedColors[slot] = vec4(color, 1.0f);
}

void main() {
  loadUniforms();
  // Grid-stride over the chunk: the host caps the group count at control.groupCap. The bounds are
  // multiplied by runtimeOne(), as the control fields are (bindings.glsl loadUniforms).
  uint first = chunk.first * runtimeOne(), end = chunk.end * runtimeOne();
  for (uint i = first + gl_GlobalInvocationID.x; i < end; i += gl_NumWorkGroups.x * SHADE_GROUP_SIZE) {
    shadeVertex(i, i - first);
  }
  checkLoopBudget();
}
