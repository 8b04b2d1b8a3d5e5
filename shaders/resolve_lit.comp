// The second resolve pass for flat and Phong shading (render.shading; resolve.glsl SHADING) and for
// scenes with textures (resolve.glsl TEXTURED), in place of resolve_small.comp: resolve_large left
// every winner's key (KEYS_ONLY), and each covered pixel of the touched bins is coloured once, from
// its winning triangle: flat and Phong light its surface there (pixel_shading.h), as the shade pass
// lights a vertex (pixels x lights, not fragments x lights); Gouraud interpolates the shaded vertex
// colours as resolve_small does; with textures either colour is times the pixel's texel (texture.h).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "gouraud.h"
#include "pixel_shading.h"
#include "texture.h"
#include "bindings.glsl"
#include "shadow_rays.h"
#include "resolve.glsl"

// The scene's lights, as the shade pass has them.
layout(constant_id = SPEC_LIGHT_COUNT) const uint LIGHT_COUNT = 0u;
layout(constant_id = SPEC_SPECULAR) const bool SPECULAR = true;
layout(constant_id = SPEC_CONSTANT_ATTENUATION) const bool CONSTANT_ATTENUATION = false;
layout(constant_id = SPEC_BLINN) const bool BLINN = false;
layout(constant_id = SPEC_SHADOWS) const bool SHADOWS = false;  // as the shade pass has it

// The texel triangle `tri` (material m) shows where its barycentrics are `bary`: white where
// neither the material nor the mesh has a texture.
uint pixelTexel(uvec3 v, MaterialData m, vec2 bary) {
  VertexUv a = vertexUv(v.x), b = vertexUv(v.y), c = vertexUv(v.z);
  uint texture = textureOf(m, a);
  if (texture == TEXTURE_NONE) return VERTEX_WHITE;
  TextureTaps k = textureTaps(textureData(texture), interpolateUv(a.uv, b.uv, c.uv, bary), frame.textureFilter);
  return blendTaps(poolTexel(k.i00), poolTexel(k.i10), poolTexel(k.i01), poolTexel(k.i11), k);
}

// Triangle `id`'s colour at pixel (x, y): Gouraud's, or its surface flat or Phong, lit, times its
// texel; packed.
uint pixelColor(uint id, int x, int y) {
  uvec4 tri = TEXEL(triangleTexels, id);
  uvec3 v = cornerVertices(id, tri);
  ObjectData object = objectData(tri.w);
  MaterialData m = materialData(object.material);
  GouraudTriangle g;
  vec2 bary = vec2(0.0f);
  if (TEXTURED || SHADING != SHADING_FLAT) {
    g = loadGouraud(id);
    bary = barycentrics(g, pixelRay(x, y, frame.principal), INTERPOLATION);
  }
  uint texel = TEXTURED ? pixelTexel(v, m, bary) : VERTEX_WHITE;
  if (SHADING == SHADING_GOURAUD) return packColor(texturedColor(interpolateColorAt(g, bary), texel));
  VertexIn a = posedVertex(vertexIn(v.x), object), b = posedVertex(vertexIn(v.y), object),
           c = posedVertex(vertexIn(v.z), object);
  SurfacePoint s;
  if (SHADING == SHADING_FLAT) {
    s = isQuad(id) ? flatQuadSurface(a, b, object.lightOffset, m) : flatSurface(a, b, c, object.lightOffset, m);
  } else {
    s = phongSurface(a, b, c, object.lightOffset, m, bary);
  }
  if (TEXTURED) s.m.color = texturedColor(s.m.color, texel);
  vec3 V = viewVector(s.P, frame);
  vec3 color = phongAmbient(s.m, frame.ambient);
  for (uint l = 0u; l < LIGHT_COUNT; ++l) {
    LightData light = lightData(l);
    vec3 lit = phongLightWith(s.P, s.N, V, s.m, light, SPECULAR, CONSTANT_ATTENUATION, BLINN);
    if (SHADOWS) lit = shadowedTerm(0u, light, lit, s.P, v);
    color += lit;
  }
  return packColor(isQuad(id) && isUnlit(s.N) ? s.m.color : color);
}

#include "resolve_keys.glsl"
