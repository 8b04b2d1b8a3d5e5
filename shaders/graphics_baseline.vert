// Graphics-pipeline baseline (graphics/graphics_renderer.h), vertex stage: the transform and Phong of
// shade_vertices.comp (phong.h), then the homogeneous pixel-space position mapped to Vulkan clip
// space. Vertices are pulled from the texel buffer by gl_VertexIndex (an indexed draw, so the
// driver's vertex cache shades a shared vertex once per batch), as the compute port reads them:
// pulling from a storage buffer measured the same as vertex attributes on lavapipe
// (docs/PERFORMANCE.md, "Shade"), and it keeps VertexIn's layout in shared.h alone, with no
// attribute-format table to keep in step.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#define PHONGVK_GRAPHICS_STAGE  // bindings.glsl: no workgroups here
#include "phong.h"
#include "bindings.glsl"

// INTERP_PERSPECTIVE or INTERP_SCREEN (FrameData.interpolation); one pipeline per mode.
layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;
// The scene's light count (fixed per renderer), as the compute port's shade pass has it. A loop
// bound read from the uniform block made lavapipe 22.3 inline it and compile the vertex shader
// anew at every draw, keeping every copy (bindings.glsl loadFrame): the baseline paid that each
// frame, and the process grew.
layout(constant_id = SPEC_LIGHT_COUNT) const uint LIGHT_COUNT = 0u;

// The Gouraud colour, interpolated perspective-correctly by the hardware. For screen-linear
// interpolation it is (colour * W, W): the interpolated ratio sum(b_i W_i c_i) / sum(b_i W_i) is
// exactly the reference's screen-space barycentrics (gouraud.h interpolateColor), also for
// triangles the near plane clips, where `noperspective` would interpolate linearly across the
// clipped polygon instead and disagree with the reference.
layout(location = 0) out vec4 gouraud;

// h = (X, Y, z) -> clip space, with W = homogeneousW(h): z with a perspective camera, 1 with an
// orthographic one. The screen position is principal + (X, Y) / W and Vulkan's NDC run from -1 to
// 1 across the image with y down like ours, so x_ndc = (X / W + principal.x) * 2 / width - 1. Depth
// is reversed-Z: z_ndc = near (far - z) / ((far - near) W) is 1 at the near plane and 0 at the far
// plane, so the hardware's clipping (0 <= z <= w) is exactly near <= z <= far, and a float depth
// buffer keeps the relative precision of z at every distance (hyperbolic z / w meets float's dense
// exponents near 0). An orthographic depth is linear in z: (far - z) / (far - near).
vec4 clipPosition(vec3 h) {
  vec2 size = vec2(frame.width, frame.height);
  float w = homogeneousW(h, frame.projection);
  vec2 xy = h.xy * (2.0f / size) + w * (frame.principal * (2.0f / size) - 1.0f);
  float nearScale = frame.projection == PROJECTION_ORTHOGRAPHIC ? 1.0f : frame.nearPlane;
  float z = nearScale * (frame.farPlane - h.z) / (frame.farPlane - frame.nearPlane);
  return vec4(xy, z, w);
}

void main() {
  loadUniforms();
  VertexIn stored = vertexIn(gl_VertexIndex);
  ObjectData object = objectData(stored.object);
  VertexIn v = posedVertex(stored, object);
  MaterialData m = vertexMaterial(materialData(object.material), v.color);
  vec3 h = toHomogeneous(v.position, object.viewOffset, frame);
  gl_Position = clipPosition(h);
  vec3 P = lightingPosition(v.position, object.lightOffset);
  vec3 V = viewVector(P, frame);
  vec3 color = phongAmbient(m, frame.ambient);
  for (uint l = 0u; l < LIGHT_COUNT; ++l) color += phongLight(P, v.normal, V, m, lightData(l));
  float w = homogeneousW(h, frame.projection);
  gouraud = INTERPOLATION == INTERP_SCREEN ? vec4(color * w, w) : vec4(color, 1.0f);
}
