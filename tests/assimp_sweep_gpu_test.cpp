// assimp_sweep_gpu_test.cpp — every model of Debian's assimp-testmodels that phongvk's formats cover
// (OBJ, PLY, STL, glTF and GLB, made by other tools), rendered alone as `phongvk render model` does:
// each renders with the same bytes and keys on both backends, or is refused with a SceneError that
// names the file and why, never a crash, a hang or another error. The files users expect to see
// (point clouds, lines, Draco-compressed glTF) are among those that render.
#include "test_util.h"

#include <phongvk/phongvk.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace phongvk {
namespace {

const std::string kModels = "/usr/share/assimp/models/";

std::vector<std::string> modelFiles() {
  std::vector<std::string> files;
  if (!std::filesystem::is_directory(kModels)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(kModels)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (entry.is_regular_file() && (ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".gltf" || ext == ".glb"))
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The model alone, small: "rendered", or the refusal's message.
std::string renderAlone(const std::string& path) {
  try {
    const Scene scene = loadScene(path).withImageSize(64, 48);
    const DiffResult result = diff(scene, RendererOptions{Backend::Gpu, -1, true});
    EXPECT_EQ(result.stats.differing, 0u) << path;
    EXPECT_TRUE(result.reference.keys == result.gpu.keys) << path;
    return "rendered";
  } catch (const SceneError& error) {
    return error.what();
  }
}

TEST(AssimpSweep, EveryModelRendersTheSameOnBothBackendsOrIsRefusedByName) {
  const std::vector<std::string> files = modelFiles();
  ASSERT_GE(files.size(), 90u) << "assimp-testmodels (scripts/setup.sh --test) is not installed";
  // Files users expect to see: point clouds, lines in every glTF mode, a Draco-compressed engine.
  const std::set<std::string> mustRender = {
      "OBJ/point_cloud.obj", "OBJ/testpoints.obj", "OBJ/testline.obj", "PLY/points.ply",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf",
      "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf",
      "glTF2/draco/2CylinderEngine.gltf"};
  size_t rendered = 0;
  std::set<std::string> renderedFiles;
  for (const std::string& path : files) {
    SCOPED_TRACE(path);
    const std::string outcome = renderAlone(path);
    const std::string relative = path.substr(kModels.size());
    if (outcome == "rendered") {
      ++rendered;
      renderedFiles.insert(relative);
      continue;
    }
    // A refusal names the file and says why after it.
    EXPECT_EQ(outcome.rfind(path + ": ", 0), 0u) << outcome;
    EXPECT_GT(outcome.size(), path.size() + 4) << outcome;
    std::printf("refused %s\n", outcome.c_str());
  }
  for (const std::string& file : mustRender) EXPECT_TRUE(renderedFiles.count(file)) << file << " was refused";
  std::printf("%zu of %zu models rendered, the same bytes on both backends\n", rendered, files.size());
  EXPECT_GE(rendered, 69u);  // 56 before points, lines and Draco, and the 13 files above
}

}  // namespace
}  // namespace phongvk
