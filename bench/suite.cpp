#include "suite.h"

#include "scene/camera.h"

#include <algorithm>
#include <filesystem>

namespace phongvk::bench {

namespace {

struct GridSize {
  const char* label;
  int n;          // n x n spheres
  int subdivide;  // 20 * 4^subdivide triangles per sphere
};

// ~1k to ~10M triangles. On lavapipe the largest array bound as one storage buffer (128 MiB) is the
// clip list, 4 bytes a triangle: up to 33.5M triangles fit; the shaded vertices are written a
// binding's worth at a time and the read-only arrays are bound as texels (2 GiB). A scene past a
// limit shows "does not fit".
constexpr GridSize GRIDS[] = {{"1k", 2, 2}, {"10k", 3, 3}, {"100k", 5, 4}, {"1M", 7, 5}, {"8M", 10, 6}, {"10M", 11, 6}};
constexpr int QUICK_GRIDS = 2;

// The smoke test renders small images: the harness is exercised, not the machine.
constexpr int QUICK_WIDTH = 320, QUICK_HEIGHT = 180;

std::string gridName(const GridSize& g) {
  return std::string("grid ") + g.label + " (" + std::to_string(g.n) + "x" + std::to_string(g.n) + ", subdivide " +
         std::to_string(g.subdivide) + ")";
}

std::function<SceneSpec()> fromFile(const std::string& path) {
  return [path] { return loadSceneSpec(path); };
}

std::function<SceneSpec()> atSize(std::function<SceneSpec()> load, int width, int height) {
  return [load, width, height] {
    SceneSpec scene = load();
    scene.camera = withImageSize(scene.camera, width, height);
    return scene;
  };
}

std::function<SceneSpec()> grid(const GridSize& g) {
  return [g] { return icosphereGrid(g.n, g.subdivide); };
}

// A box far wider than the view, seen from 1 m above looking steeply down: two triangles cover
// every pixel, the opposite extreme of the grids.
SceneSpec screenFillingFloor() {
  SceneSpec scene;
  scene.path = "screen-filling floor";
  scene.camera.position = {0, 0, 1};
  scene.camera.direction = {0, 0.3, -1};  // the top edge of the 60 degree view still looks down
  scene.lights.push_back({{0.5, 1, 2}, 1.0f, {1, 1, 1}});
  scene.materials.push_back({0.1f, 0.9f, 0.3f, 8.0f, {1, 0.1f, 0.05f}, {0.8f, 0.75f, 0.7f}});
  Object floor;
  floor.shape = Shape::Polyhedron;
  for (double x : {-50.0, 50.0}) {
    for (double y : {-50.0, 50.0}) {
      for (double z : {-0.1, 0.0}) floor.points.push_back({x, y, z});
    }
  }
  floor.jsonPath = "objects[0]";
  scene.objects.push_back(floor);
  return scene;
}

std::vector<SuiteScene> paperScenes(const std::string& sourceDir) {
  std::vector<std::string> files;
  const std::filesystem::path folder = std::filesystem::path(sourceDir) / "scenes" / "paper";
  if (std::filesystem::is_directory(folder)) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<SuiteScene> scenes;
  for (const std::string& file : files) {
    scenes.push_back({"paper/" + std::filesystem::path(file).stem().string(), "paper", fromFile(file)});
  }
  return scenes;
}

std::vector<SuiteScene> fullSuite(const std::string& sourceDir) {
  std::vector<SuiteScene> suite = paperScenes(sourceDir);
  for (const GridSize& g : GRIDS) suite.push_back({gridName(g), "grid", grid(g), true});
  const std::string floorAndWalls = sourceDir + "/scenes/floor_and_walls.json";
  suite.push_back({"floor_and_walls", "large triangles", fromFile(floorAndWalls)});
  suite.push_back({"screen-filling floor", "large triangles", screenFillingFloor});
  const int W = 3840, H = 2160;
  suite.push_back({"basic @ 4K", "4K", atSize(fromFile(sourceDir + "/scenes/basic.json"), W, H)});
  suite.push_back({"floor_and_walls @ 4K", "4K", atSize(fromFile(floorAndWalls), W, H)});
  suite.push_back({"screen-filling floor @ 4K", "4K", atSize(screenFillingFloor, W, H)});
  suite.push_back({gridName(GRIDS[3]) + " @ 4K", "4K", atSize(grid(GRIDS[3]), W, H), true});
  return suite;
}

std::vector<SuiteScene> quickSuite(const std::string& sourceDir) {
  std::vector<SuiteScene> suite = paperScenes(sourceDir);
  suite.resize(std::min<size_t>(suite.size(), 1));
  for (int i = 0; i < QUICK_GRIDS; ++i) suite.push_back({gridName(GRIDS[i]), "grid", grid(GRIDS[i]), true});
  suite.push_back({"floor_and_walls", "large triangles", fromFile(sourceDir + "/scenes/floor_and_walls.json")});
  suite.push_back({"screen-filling floor", "large triangles", screenFillingFloor});
  for (SuiteScene& s : suite) s.load = atSize(s.load, QUICK_WIDTH, QUICK_HEIGHT);
  return suite;
}

}  // namespace

SceneSpec icosphereGrid(int n, int subdivide) {
  SceneSpec scene;
  scene.path = "icosphere grid";
  const double middle = (n - 1) / 2.0;
  // The grid spans about n m; at 0.9 n + 1 m the 60 degree view holds it with a margin.
  const double distance = 0.9 * n + 1;
  scene.camera.position = {middle, -distance, middle};
  scene.camera.direction = {0, 1, 0};
  scene.lights.push_back({{middle - n / 2.0, -distance, middle + n / 2.0}, 1.0f, {1, 1, 1}});
  // No attenuation: the grid's far corners stay lit at every size.
  scene.materials.push_back({0.15f, 0.8f, 0.5f, 20.0f, {1, 0, 0}, {0.75f, 0.8f, 0.9f}});
  for (int i = 0; i < n * n; ++i) {
    Object sphere;
    sphere.shape = Shape::Icosphere;
    sphere.center = {double(i % n), 0, double(i / n)};
    sphere.radius = 0.4;
    sphere.subdivide = subdivide;
    sphere.jsonPath = "objects[" + std::to_string(i) + "]";
    scene.objects.push_back(sphere);
  }
  return scene;
}

std::vector<SuiteScene> makeSuite(const std::string& sourceDir, bool quick) {
  return quick ? quickSuite(sourceDir) : fullSuite(sourceDir);
}

std::vector<SuiteScene> makeDeviceScenes(const std::string& sourceDir, bool quick) {
  std::vector<SuiteScene> scenes;
  if (!quick) {
    scenes = paperScenes(sourceDir);
    scenes.push_back({gridName(GRIDS[3]), "grid", grid(GRIDS[3]), true});
  }
  scenes.push_back({"basic @ 240x160", "small", atSize(fromFile(sourceDir + "/scenes/basic.json"), 240, 160)});
  return scenes;
}

std::vector<SuiteScene> makeSetupScenes(bool quick) {
  std::vector<SuiteScene> scenes;
  const int grids = quick ? QUICK_GRIDS : int(std::size(GRIDS));
  for (int i = 0; i < grids; ++i) scenes.push_back({gridName(GRIDS[i]), "grid", grid(GRIDS[i]), true});
  if (!quick) {
    // One object of 5,242,880 triangles: the deepest subdivision the suite asks of the mesher.
    scenes.push_back({"icosphere, subdivide 9", "mesh", [] { return icosphereGrid(1, 9); }});
  }
  return scenes;
}

}  // namespace phongvk::bench
