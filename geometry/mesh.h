// mesh.h — the triangle mesh every library passes around, and the coordinates a mesh may hold.
#pragma once

#include "geometry/texture_image.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace phongvk {

// The largest |coordinate| and size, in metres, a scene may use (positions, centres, points,
// radii, mesh-file vertices after scaling): far beyond any useful scene, small enough that the
// offsets and squared distances the renderers take in 32-bit float cannot overflow.
inline constexpr double MAX_COORDINATE = 1e15;

// Positions are local to the object's origin (so far-away objects keep float precision);
// triangles wind counter-clockwise seen from outside (outward normal = cross(b - a, c - a)).
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // unit length, one per position
  std::vector<glm::uvec3> triangles;
  // One RGBA8 colour per position (red in the low byte) that multiplies the material's colour, or
  // none: white.
  std::vector<uint32_t> colors;
  // Texture coordinates, one per position, or none; which of `textures` each vertex samples (the
  // same at a triangle's three vertices), gpu::TEXTURE_NONE where none, one per position or none.
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> textureIds;
  std::vector<std::shared_ptr<const TextureImage>> textures;
  // What the file holds that is not rendered, for the user (RendererStats::notice); empty if nothing.
  std::string notice;
};

}  // namespace phongvk
