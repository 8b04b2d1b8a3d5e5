// mesh_load.cpp — see mesh_load.h.
#include "mesh_load.h"

#include "scene/object_mesh.h"
#include "scene/scene.h"

#include "phongvk/phongvk.h"
#include "tools/statistics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace phongvk::bench {
namespace {

namespace fs = std::filesystem;

constexpr int ROUNDS = 3;

// An n x n grid of vertices on a gentle wave: 2 (n - 1)^2 triangles, every vertex shared.
struct Grid {
  int n;
  float x(int i) const { return float(i % n) / float(n); }
  float y(int i) const { return float(i / n) / float(n); }
  float z(int i) const { return 0.05f * std::sin(float(i % n) * 0.01f) * std::cos(float(i / n) * 0.013f); }
  size_t vertices() const { return size_t(n) * n; }
  template <typename F>
  void triangles(F&& emit) const {
    for (int r = 0; r + 1 < n; ++r)
      for (int c = 0; c + 1 < n; ++c) {
        const uint32_t a = uint32_t(r * n + c), b = a + 1, d = a + uint32_t(n), e = d + 1;
        emit(a, b, e);
        emit(a, e, d);
      }
  }
  size_t triangleCount() const { return 2 * size_t(n - 1) * size_t(n - 1); }
};

template <typename T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

std::string binaryPly(const Grid& g) {
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(g.vertices()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                  std::to_string(g.triangleCount()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  s.reserve(s.size() + g.vertices() * 12 + g.triangleCount() * 13);
  for (size_t i = 0; i < g.vertices(); ++i) {
    put(s, g.x(int(i)));
    put(s, g.y(int(i)));
    put(s, g.z(int(i)));
  }
  g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
    s += char(3);
    put(s, int32_t(a));
    put(s, int32_t(b));
    put(s, int32_t(c));
  });
  return s;
}

std::string obj(const Grid& g) {
  std::string s;
  char line[96];
  for (size_t i = 0; i < g.vertices(); ++i) {
    s.append(line, size_t(std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", g.x(int(i)), g.y(int(i)), g.z(int(i)))));
  }
  g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
    s.append(line, size_t(std::snprintf(line, sizeof line, "f %u %u %u\n", a + 1, b + 1, c + 1)));
  });
  return s;
}

std::string binaryStl(const Grid& g) {
  std::string s(80, ' ');
  put(s, uint32_t(g.triangleCount()));
  g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
    for (int k = 0; k < 3; ++k) put(s, 0.0f);
    for (uint32_t v : {a, b, c}) {
      put(s, g.x(int(v)));
      put(s, g.y(int(v)));
      put(s, g.z(int(v)));
    }
    put(s, uint16_t(0));
  });
  return s;
}

std::string glb(const Grid& g) {
  std::string bin;
  for (size_t i = 0; i < g.vertices(); ++i) {
    put(bin, g.x(int(i)));
    put(bin, g.y(int(i)));
    put(bin, g.z(int(i)));
  }
  const size_t positionBytes = bin.size();
  g.triangles([&](uint32_t a, uint32_t b, uint32_t c) {
    put(bin, a);
    put(bin, b);
    put(bin, c);
  });
  std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                     R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"accessors":[)"
                     R"({"bufferView":0,"componentType":5126,"count":)" + std::to_string(g.vertices()) +
                     R"(,"type":"VEC3","min":[0,0,-0.05],"max":[1,1,0.05]},)"
                     R"({"bufferView":1,"componentType":5125,"count":)" + std::to_string(3 * g.triangleCount()) +
                     R"(,"type":"SCALAR"}],"bufferViews":[{"buffer":0,"byteLength":)" + std::to_string(positionBytes) +
                     R"(},{"buffer":0,"byteOffset":)" + std::to_string(positionBytes) + R"(,"byteLength":)" +
                     std::to_string(bin.size() - positionBytes) + R"(}],"buffers":[{"byteLength":)" +
                     std::to_string(bin.size()) + "}]}";
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string s = "glTF";
  put(s, uint32_t(2));
  put(s, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  put(s, uint32_t(json.size()));
  s += "JSON" + json;
  put(s, uint32_t(bin.size()));
  s += std::string("BIN\0", 4) + bin;
  return s;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Loads `path` as a scene's mesh object would, ROUNDS times (1 when quick); the median.
MeshLoadRun load(const std::string& format, const fs::path& path, bool judged, int rounds) {
  MeshLoadRun run{format, path.filename().string()};
  run.judged = judged;
  run.megabytes = double(fs::file_size(path)) / 1e6;
  std::vector<double> times;
  try {
    Object object;
    object.shape = Shape::Mesh;
    object.file = path.string();
    object.jsonPath = "objects[0]";
    for (int r = 0; r < rounds; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const ObjectMesh mesh = buildObjectMesh(object);
      times.push_back(secondsSince(start));
      run.triangles = mesh.mesh.triangles.size();
    }
    run.seconds = median(times);
  } catch (const std::exception& e) {
    run.failure = e.what();
  }
  return run;
}

}  // namespace

std::vector<MeshLoadRun> runMeshLoads(bool quick) {
  const fs::path dir = fs::temp_directory_path() / ("phongvk_bench_meshes_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const Grid large{quick ? 100 : 2237};  // 10.0M triangles
  const Grid medium{quick ? 100 : 708};  // 1.0M triangles
  struct File {
    std::string format, name;
    const Grid* grid;
    std::string (*write)(const Grid&);
    bool judged;
  };
  const std::vector<File> files = {{"binary PLY", "grid.ply", &large, binaryPly, true},
                                   {"OBJ", "grid.obj", &medium, obj, true},
                                   {"binary PLY", "grid_1m.ply", &medium, binaryPly, false},
                                   {"binary STL", "grid.stl", &medium, binaryStl, false},
                                   {"GLB", "grid.glb", &medium, glb, false}};
  std::vector<MeshLoadRun> runs;
  for (const File& f : files) {
    {
      std::ofstream out(dir / f.name, std::ios::binary);
      const std::string bytes = f.write(*f.grid);
      out.write(bytes.data(), std::streamsize(bytes.size()));
    }
    runs.push_back(load(f.format, dir / f.name, f.judged, quick ? 1 : ROUNDS));
    fs::remove(dir / f.name);
    const MeshLoadRun& r = runs.back();
    std::printf("  load %-10s %-12s %9zu triangles %7.1f MB: %s\n", r.format.c_str(), r.file.c_str(), r.triangles,
                r.megabytes, r.failure.empty() ? (std::to_string(r.seconds) + " s").c_str() : r.failure.c_str());
  }
  fs::remove_all(dir);
  return runs;
}

}  // namespace phongvk::bench
