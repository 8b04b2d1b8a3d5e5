// moving_object.h — what moving one object costs against moving the camera (a robot arm, a
// dataset of object poses): the public Renderer, a 1M-triangle mesh added by handle, a new pose
// each frame (Scene::setPose) against a new camera each frame, interleaved.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk::bench {

// A frame with the object moved within this factor of a frame with the camera moved.
inline constexpr double MOVING_OBJECT_TARGET = 1.1;
// Interleaved rounds, each of this many frames each way (the medians are over all of them).
inline constexpr int MOVING_OBJECT_ROUNDS = 5, MOVING_OBJECT_FRAMES = 10;

struct MovingObjectRun {
  std::string name;           // "gpu, 1002528 triangles"
  std::string backend;        // "gpu" or "cpu"
  size_t triangles = 0;
  int width = 0, height = 0;
  double cameraMs = 0;        // a frame whose camera moved, median
  double objectMs = 0;        // a frame whose object moved (a rotation and a translation), median
  uint64_t builds = 0;        // meshes built during the moving frames (RendererStats::sceneBuilds; 0: none)
  std::string failure;
  double ratio() const { return objectMs / cameraMs; }
};

// `quick`: a 20,000-triangle mesh, one round; else 1M triangles.
std::vector<MovingObjectRun> runMovingObjects(bool quick);

}  // namespace phongvk::bench
