// The second resolve pass for flat and Phong shading (render.shading; resolve.glsl SHADING), in
// place of resolve_small.comp: resolve_large left every winner's key (KEYS_ONLY), and each covered
// pixel of the touched bins is lit once, from its winning triangle's surface there
// (pixel_shading.h), as the shade pass lights a vertex: pixels x lights, not fragments x lights.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "gouraud.h"
#include "pixel_shading.h"
#include "bindings.glsl"
#include "resolve.glsl"

// The scene's lights, as the shade pass has them.
layout(constant_id = SPEC_LIGHT_COUNT) const uint LIGHT_COUNT = 0u;
layout(constant_id = SPEC_SPECULAR) const bool SPECULAR = true;
layout(constant_id = SPEC_CONSTANT_ATTENUATION) const bool CONSTANT_ATTENUATION = false;
layout(constant_id = SPEC_BLINN) const bool BLINN = false;

// Triangle `id`'s surface at pixel (x, y), flat or Phong, lit and packed.
uint pixelColor(uint id, int x, int y) {
  uvec4 tri = texelFetch(triangleTexels, int(id));
  ObjectData object = objectData(tri.w);
  MaterialData m = materialData(object.material);
  VertexIn a = vertexIn(tri.x), b = vertexIn(tri.y), c = vertexIn(tri.z);
  SurfacePoint s;
  if (SHADING == SHADING_FLAT) {
    s = flatSurface(a, b, c, object.lightOffset, m);
  } else {
    vec2 bary = barycentrics(loadGouraud(id), pixelRay(x, y, frame.principal), INTERPOLATION);
    s = phongSurface(a, b, c, object.lightOffset, m, bary);
  }
  vec3 V = viewVector(s.P, frame);
  vec3 color = phongAmbient(s.m, frame.ambient);
  for (uint l = 0u; l < LIGHT_COUNT; ++l) {
    color += phongLightWith(s.P, s.N, V, s.m, lightData(l), SPECULAR, CONSTANT_ATTENUATION, BLINN);
  }
  return packColor(color);
}

#include "resolve_keys.glsl"
