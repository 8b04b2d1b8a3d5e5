#include "reference/render_reference.h"

#include "image/packed_pixels.h"
#include "shaders/gouraud.h"
#include "shaders/shadow_rays.h"
#include "shaders/phong.h"
#include "shaders/pixel_shading.h"
#include "shaders/texture.h"
#include "shaders/triangle_setup.h"

#include <algorithm>

namespace phongvk {

using namespace gpu;

std::vector<ShadedVertex> shadeVertices(const SceneData& data, const FrameInputs& in) {
  std::vector<ShadedVertex> shaded(data.vertices.size());
  for (size_t i = 0; i < data.vertices.size(); ++i) {
    const ObjectData& object = in.objects[data.vertices[i].object];
    const VertexIn v = posedVertex(data.vertices[i], object);
    const MaterialData m = vertexMaterial(in.materials[object.material], v.color);
    const vec3 P = lightingPosition(v.position, object.lightOffset);
    const vec3 V = viewVector(P, in.frame);
    const bool blinn = in.frame.specular == SPECULAR_BLINN;
    vec3 color = phongAmbient(m, in.frame.ambient);
    for (const LightData& light : in.lights) {
      vec3 lit = phongLightModel(P, v.normal, V, m, light, blinn);
      if (in.shadows) lit = shadowedTerm(*in.shadows, light, lit, P, vertexOwners(uint32_t(i)));
      color += lit;
    }
    if (isUnlit(v.normal)) color = m.color;  // a point's or a line's vertex given no normal
    shaded[i].hpos = vec4(toHomogeneous(v.position, object.viewOffset, in.frame), 1.0f);
    shaded[i].color = vec4(color, 1.0f);
  }
  return shaded;
}

std::vector<uint64_t> rasterize(const SceneData& data, const std::vector<ShadedVertex>& shaded,
                                const FrameData& frame) {
  std::vector<uint64_t> keys(static_cast<size_t>(frame.width) * frame.height, KEY_CLEAR);
  for (uint32_t id = 0; id < data.triangles.size(); ++id) {
    const bool cullBack = !isQuadRecord(data, id) && (data.objects[data.triangles[id].w].flags & OBJECT_CULL_BACK) != 0;
    const auto corners = recordShaded(data, frame, id, [&](uint32_t v) { return shaded[v]; });
    TriangleSetup t;
    if (!setupTriangle(vec3(corners[0].hpos), vec3(corners[1].hpos), vec3(corners[2].hpos), cullBack, id, frame, t)) {
      continue;
    }
    for (int k = 0; k + 2 < t.count; ++k) {
      EdgeSetup s;
      if (!setupFan(t, k, frame, s)) continue;
      for (int y = s.bbox.y; y <= s.bbox.w; ++y) {
        for (int x = s.bbox.x; x <= s.bbox.z; ++x) {
          uint64_t& pixel = keys[static_cast<size_t>(y) * frame.width + x];
          pixel = std::min(pixel, fragmentKey(t, s, x, y, frame));
        }
      }
    }
  }
  return keys;
}

namespace {

// The barycentrics of pixel (x, y) in the triangle with shaded corners `s`.
vec2 pixelBarycentrics(const FrameData& frame, const std::array<ShadedVertex, 3>& s, int x, int y) {
  return barycentrics(gouraudTriangle(s[0], s[1], s[2], frame.projection), pixelRay(x, y, frame.principal),
                      frame.interpolation);
}

// Flat or Phong shading's surface of record `id` with the pixel's barycentrics `bary` (unused
// with flat shading).
SurfacePoint surfaceAt(const SceneData& data, const FrameInputs& in, uint32_t id, vec2 bary) {
  const glm::uvec3 v = cornerVertices(data, id);
  const ObjectData& object = in.objects[data.triangles[id].w];
  const MaterialData& m = in.materials[object.material];
  const VertexIn a = posedVertex(data.vertices[v.x], object), b = posedVertex(data.vertices[v.y], object),
                 c = posedVertex(data.vertices[v.z], object);
  if (in.frame.shading == SHADING_FLAT) {
    return isQuadRecord(data, id) ? flatQuadSurface(a, b, object.lightOffset, m) : flatSurface(a, b, c, object.lightOffset, m);
  }
  return phongSurface(a, b, c, object.lightOffset, m, bary);
}

// The texel record `id` shows where its barycentrics are `bary` (texture.h): white in a scene
// without textures and where neither its material nor its mesh has one.
uint32_t pixelTexel(const SceneData& data, const FrameInputs& in, uint32_t id, vec2 bary) {
  if (data.uvs.empty()) return VERTEX_WHITE;
  const glm::uvec3 v = cornerVertices(data, id);
  const VertexUv &a = data.uvs[v.x], &b = data.uvs[v.y], &c = data.uvs[v.z];
  const uint32_t texture = textureOf(in.materials[in.objects[data.triangles[id].w].material], a);
  if (texture == TEXTURE_NONE) return VERTEX_WHITE;
  const TextureTaps k = textureTaps(data.textures[texture], interpolateUv(a.uv, b.uv, c.uv, bary), in.frame.textureFilter);
  return blendTaps(pooledTexel(data, texture, k.i00), pooledTexel(data, texture, k.i10), pooledTexel(data, texture, k.i01),
                   pooledTexel(data, texture, k.i11), k);
}

// Flat or Phong shading, or any shading in a scene with textures: triangle `tri`'s colour at pixel
// (x, y), Gouraud's interpolated or its surface lit with the frame's lights, times its texel.
uint32_t litPixel(const SceneData& data, const FrameInputs& in, const std::array<ShadedVertex, 3>& corners,
                  uint32_t id, int x, int y) {
  const FrameData& frame = in.frame;
  const bool textured = !data.uvs.empty();
  const vec2 bary = textured || frame.shading != SHADING_FLAT ? pixelBarycentrics(frame, corners, x, y) : vec2(0.0f);
  const uint32_t texel = pixelTexel(data, in, id, bary);
  if (frame.shading == SHADING_GOURAUD) {
    const GouraudTriangle g = gouraudTriangle(corners[0], corners[1], corners[2], frame.projection);
    return packColor(texturedColor(interpolateColorAt(g, bary), texel));
  }
  SurfacePoint s = surfaceAt(data, in, id, bary);
  if (textured) s.m.color = texturedColor(s.m.color, texel);
  const vec3 V = viewVector(s.P, frame);
  vec3 color = phongAmbient(s.m, frame.ambient);
  for (const LightData& light : in.lights) {
    vec3 lit = phongLightModel(s.P, s.N, V, s.m, light, frame.specular == SPECULAR_BLINN);
    if (in.shadows) lit = shadowedTerm(*in.shadows, light, lit, s.P, cornerVertices(data, id));
    color += lit;
  }
  return packColor(isQuadRecord(data, id) && isUnlit(s.N) ? s.m.color : color);
}

}  // namespace

SurfacePoint pixelSurface(const SceneData& data, const FrameInputs& in, uint32_t id,
                          const std::array<ShadedVertex, 3>& corners, int x, int y) {
  const bool flat = in.frame.shading == SHADING_FLAT;  // the face's surface: no barycentrics
  return surfaceAt(data, in, id, flat ? vec2(0.0f) : pixelBarycentrics(in.frame, corners, x, y));
}

Image resolve(const SceneData& data, const FrameInputs& in, const std::vector<ShadedVertex>& shaded,
              const std::vector<uint64_t>& keys) {
  const FrameData& frame = in.frame;
  std::vector<uint32_t> packed(keys.size());
  const uint32_t background = packColor(frame.background);
  for (uint32_t y = 0; y < frame.height; ++y) {
    for (uint32_t x = 0; x < frame.width; ++x) {
      const size_t i = static_cast<size_t>(y) * frame.width + x;
      if (keys[i] == KEY_CLEAR) {
        packed[i] = background;
        continue;
      }
      const uint32_t id = static_cast<uint32_t>(keys[i]);
      const auto corners = recordShaded(data, frame, id, [&](uint32_t v) { return shaded[v]; });
      packed[i] = frame.shading == SHADING_GOURAUD && data.uvs.empty()
                      ? resolvePixel(corners[0], corners[1], corners[2], int(x), int(y), frame, frame.interpolation)
                      : litPixel(data, in, corners, id, int(x), int(y));
    }
  }
  return imageFromPacked(packed, int(frame.width), int(frame.height));
}

RenderOutput renderReference(const SceneData& data, const FrameInputs& in) {
  const std::vector<ShadedVertex> shaded = shadeVertices(data, in);
  RenderOutput out;
  out.keys = rasterize(data, shaded, in.frame);
  out.image = resolve(data, in, shaded, out.keys);
  return out;
}

}  // namespace phongvk
