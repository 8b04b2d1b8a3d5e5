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

// A light a mesh file places (glTF KHR_lights_punctual), in the file's coordinates as its positions
// are, with the file's own units (docs/DESIGN.md "Lights from files" converts them).
struct MeshLight {
  enum class Kind { Point, Spot, Directional };
  Kind kind = Kind::Point;
  glm::dvec3 position = {0, 0, 0};     // point and spot
  glm::dvec3 direction = {0, 0, -1};   // spot: the way it points; directional: the way its light travels
  glm::dvec3 color = {1, 1, 1};
  double intensity = 1;                // candela (point, spot) or lux (directional)
  double range = 0;                    // metres; 0: none
  double innerCone = 0, outerCone = 45;  // spot: half-angles, degrees
  std::string name;                    // "KHR_lights_punctual.lights[i]", for messages
};

// Positions are local to the object's origin (so far-away objects keep float precision);
// triangles wind counter-clockwise seen from outside (outward normal = cross(b - a, c - a)).
// Points and line segments are drawn a fixed number of pixels wide (docs/DESIGN.md "Points and
// lines"); a mesh has triangles, points or lines, or any mix of them.
struct Mesh {
  std::vector<glm::vec3> positions;
  // One per position: unit length, or (0, 0, 0) for a vertex only points and lines use that was
  // given no normal (drawn unlit: its colour as it is).
  std::vector<glm::vec3> normals;
  std::vector<glm::uvec3> triangles;
  std::vector<uint32_t> points;      // vertex indices, each drawn as a point
  std::vector<glm::uvec2> lines;     // vertex index pairs, each drawn as a segment
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
  // The lights the file places; taken out by whoever builds the object (scene/object_mesh.h).
  std::vector<MeshLight> lights;
};

}  // namespace phongvk
