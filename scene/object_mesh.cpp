// object_mesh.cpp — buildObjectMesh: picks the shape's builder, checks the size it will reach, then
// subdivides. Primitives come with their normals; the hull gets flat faces; OBJ files bring or
// compute theirs.
#include "scene/object_mesh.h"

#include "base/number_text.h"
#include "geometry/hull.h"
#include "geometry/primitives.h"
#include "geometry/subdivide.h"
#include "geometry/transform.h"
#include "meshio/mesh_file.h"
#include "meshio/mesh_import.h"

#include <cmath>
#include <cstdint>
#include <string>

namespace phongvk {

LinearTransform objectTransform(const Object& object) {
  glm::dmat3 up(1.0);
  if (object.up == UpAxis::Y) up = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  const glm::dmat3 scale(glm::dvec3(object.scale.x, 0, 0), glm::dvec3(0, object.scale.y, 0),
                         glm::dvec3(0, 0, object.scale.z));
  LinearTransform t;
  t.matrix = object.rotation * scale * up;
  t.identity = t.matrix == glm::dmat3(1.0);
  t.keepsDirections = object.up == UpAxis::Z && object.rotation == glm::dmat3(1.0) && object.scale.x > 0 &&
                      object.scale.x == object.scale.y && object.scale.y == object.scale.z;
  t.normalMatrix = glm::transpose(glm::inverse(t.matrix));
  t.mirrors = glm::determinant(t.matrix) < 0.0;
  return t;
}

namespace {

// Indices are 32-bit and every renderer holds the whole mesh in memory: 2^26 = 67M triangles is
// ~1.6 GB of positions, normals and indices — far past any scene that renders in useful time.
constexpr uint64_t kMaxTriangles = uint64_t(1) << 26;

[[noreturn]] void fail(const Object& object, const std::string& field, const std::string& why) {
  throw SceneError(object.jsonPath + "." + field + ": " + why);
}

void requirePositive(const Object& object, const char* field, double value) {
  if (!(value > 0.0) || !std::isfinite(value))
    fail(object, field, "must be a positive number, got " + std::to_string(value));
}

// Parameters the scene loader validates already; checked again so that a hand-made Object cannot
// build a broken mesh.
void checkParameters(const Object& object) {
  if (object.subdivide < 0)
    fail(object, "subdivide", "must be >= 0, got " + std::to_string(object.subdivide));
  switch (object.shape) {
    case Shape::Cube: requirePositive(object, "size", object.size); break;
    case Shape::Cone:
      if (object.rings < 1)
        fail(object, "rings", "must be >= 1, got " + std::to_string(object.rings));
      [[fallthrough]];
    case Shape::Cylinder: requirePositive(object, "height", object.height); [[fallthrough]];
    case Shape::Sphere:
      if (object.segments < 3)
        fail(object, "segments", "must be >= 3, got " + std::to_string(object.segments));
      [[fallthrough]];
    case Shape::Icosphere: requirePositive(object, "radius", object.radius); break;
    case Shape::Mesh: break;
    case Shape::Polyhedron: break;
  }
}

}  // namespace

uint64_t baseTriangles(const Object& object) {
  const uint64_t s = uint64_t(object.segments);
  switch (object.shape) {
    case Shape::Cube: return 12;
    case Shape::Sphere: return 2 * s * uint64_t(std::max(2, object.segments / 2) - 1);
    case Shape::Icosphere: return 20;
    case Shape::Cylinder: return 4 * s;
    case Shape::Cone: return 2 * s * uint64_t(object.rings);
    case Shape::Polyhedron:
    case Shape::Mesh: return 0;  // known once built
  }
  return 0;
}

namespace {

void checkSize(const Object& object, uint64_t triangles) {
  uint64_t total = triangles;
  for (int level = 0; level < object.subdivide && total <= kMaxTriangles; ++level) total *= 4;
  if (total > kMaxTriangles)
    fail(object, object.subdivide > 0 ? "subdivide" : "segments",
         "the mesh would have more than " + std::to_string(kMaxTriangles) + " triangles");
}

// Flat-shaded hull: every triangle its own three vertices with the face normal.
SurfaceMesh makePolyhedron(const Object& object, glm::dvec3 origin) {
  Hull hull = convexHull(object.points);
  if (!hull.error.empty()) fail(object, "points", hull.error);
  SurfaceMesh m;
  for (const glm::uvec3& t : hull.triangles) {
    const glm::dvec3 a = object.points[t.x] - origin, b = object.points[t.y] - origin,
                     c = object.points[t.z] - origin;
    const glm::vec3 normal(glm::normalize(glm::cross(b - a, c - a)));
    const uint32_t first = uint32_t(m.mesh.positions.size());
    for (const glm::dvec3& p : {a, b, c}) {
      m.mesh.positions.push_back(glm::vec3(p));
      m.mesh.normals.push_back(normal);
      m.surfaces.push_back(0);
    }
    m.mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return m;
}

glm::dvec3 centroid(const std::vector<glm::dvec3>& points) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : points) sum += p;
  return points.empty() ? sum : sum / double(points.size());
}

// The file's lights turned by the object's transform as its vertices are: positions and directions
// by its matrix (a direction made unit again); range and intensity as the file says (glTF: node
// transforms do not change them).
std::vector<MeshLight> turnedLights(std::vector<MeshLight> lights, const LinearTransform& t, const std::string& where) {
  for (MeshLight& light : lights) {
    light.position = t.matrix * light.position;
    light.direction = glm::normalize(t.matrix * light.direction);
    for (int axis = 0; axis < 3; ++axis) {
      if (!(std::abs(light.position[axis]) <= MAX_COORDINATE))
        throw SceneError(where + ": " + light.name + " after the object's scale and rotation is at " +
                         formatNumber(light.position[axis]) + ", beyond the " + formatNumber(MAX_COORDINATE) +
                         " m a scene may use");
    }
  }
  return lights;
}

// A mesh file, with the object's transform (before subdivision: computed normals follow the
// transformed surface), and the lights it places unless the object leaves them out.
Mesh importFile(const Object& object, std::vector<MeshLight>& lights) {
  const std::string where = object.jsonPath + ".file";
  const MeshFormat format = meshFormat(object.file, where);
  const LinearTransform transform = objectTransform(object);
  Mesh loaded = importMeshFile(object.file, format, object.baseColors, where);
  if (object.fileLights) lights = turnedLights(std::move(loaded.lights), transform, where + ": " + object.file);
  loaded.lights.clear();
  return finishLoadedMesh(std::move(loaded), transform, where + ": " + object.file);
}

SurfaceMesh makeShape(const Object& object, glm::dvec3& origin, std::vector<MeshLight>& lights) {
  origin = object.center;
  switch (object.shape) {
    case Shape::Cube: return makeCube(object.size);
    case Shape::Sphere: return makeUvSphere(object.radius, object.segments);
    case Shape::Icosphere: return makeIcosphere(object.radius);
    case Shape::Cylinder: return makeCylinder(object.radius, object.height, object.segments);
    case Shape::Cone: return makeCone(object.radius, object.height, object.segments, object.rings);
    case Shape::Polyhedron: origin = centroid(object.points); return makePolyhedron(object, origin);
    case Shape::Mesh: {
      origin = object.translate;
      SurfaceMesh m;  // flat rule: imported surfaces are whatever the file (or the arrays) say
      // Not `arrays ? *arrays : importFile(object)`: that conditional copies the imported mesh
      // (GCC 12), a large part of loading a big mesh file (docs/PERFORMANCE.md, "Mesh loading").
      if (object.arrays) {
        m.mesh = *object.arrays;
      } else {
        m.mesh = importFile(object, lights);
      }
      m.surfaces.assign(m.mesh.positions.size(), 0);
      return m;
    }
  }
  fail(object, "shape", "unknown shape");
}

}  // namespace

ObjectMesh buildObjectMesh(const Object& object) {
  checkParameters(object);
  checkSize(object, baseTriangles(object));
  ObjectMesh result;
  SurfaceMesh shape = makeShape(object, result.origin, result.lights);
  checkSize(object, shape.mesh.triangles.size());
  subdivide(shape, object.subdivide);
  result.mesh = std::move(shape.mesh);
  if (object.shape != Shape::Mesh || object.arrays) transformMesh(result.mesh, objectTransform(object), object.jsonPath + ".scale");
  result.closed = object.closed;
  return result;
}

}  // namespace phongvk
