// dataset — N views of a model from a sphere of camera poses, from C++ with no scene file: RGB
// PNGs, depth (.npy, float32 metres along the camera axis), object masks (PNG) and cameras.json
// with the intrinsics and the camera-to-world poses (OpenCV axes), as examples/python/dataset.py.
//
//   dataset MODEL OUT_DIR [VIEWS [gpu|cpu]]
#include <phongvk/npy.h>
#include <phongvk/phongvk.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace phongvk;

// The camera-to-world pose (OpenCV: x right, y down, z forward) of an eye looking at `target`, z up.
Matrix4 lookAtPose(const Vec3& eye, const Vec3& target) {
  Vec3 f = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
  const double length = std::hypot(f[0], f[1], f[2]);
  for (double& v : f) v /= length;
  const double across = std::hypot(f[0], f[1]);
  const Vec3 r = {f[1] / across, -f[0] / across, 0};  // forward x up (0, 0, 1), normalized: right
  const Vec3 d = {f[1] * r[2] - f[2] * r[1], f[2] * r[0] - f[0] * r[2], f[0] * r[1] - f[1] * r[0]};  // f x r: down
  return {r[0], d[0], f[0], eye[0], r[1], d[1], f[1], eye[1], r[2], d[2], f[2], eye[2], 0, 0, 0, 1};
}

int main(int argc, char** argv) try {
  if (argc < 3) return std::fprintf(stderr, "usage: dataset MODEL OUT_DIR [VIEWS [gpu|cpu]]\n"), 2;
  const std::string out = argv[2];
  const int views = argc > 3 ? std::stoi(argv[3]) : 12, width = 640, height = 480;
  const double f = 500, cx = (width - 1) / 2.0, cy = (height - 1) / 2.0;
  Scene scene(width, height);  // the default camera and a light at the camera
  scene.add(TriangleMesh::fromFile(argv[1]));
  const auto [low, high] = scene.bounds();
  const Vec3 centre = {(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2};
  const double distance = 1.25 * std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  Renderer renderer(argc > 4 ? parseBackend(argv[4]) : Backend::Gpu);
  std::ofstream cameras(out + "/cameras.json");
  cameras.precision(17);  // the poses as exactly as they were rendered
  cameras << "{\"intrinsics\": {\"fx\": " << f << ", \"fy\": " << f << ", \"cx\": " << cx << ", \"cy\": " << cy
          << ", \"width\": " << width << ", \"height\": " << height << "}, \"convention\": \"opencv\", \"views\": [";
  for (int i = 0; i < views; ++i) {  // a Fibonacci spiral over the sphere, poles left out
    const double z = 0.9 * (1 - 2 * (i + 0.5) / views), a = i * M_PI * (3 - std::sqrt(5.0)), s = std::sqrt(1 - z * z);
    const Vec3 eye = {centre[0] + distance * s * std::cos(a), centre[1] + distance * s * std::sin(a), centre[2] + distance * z};
    const Matrix4 pose = lookAtPose(eye, centre);
    scene.setCamera(cameraFromIntrinsics(f, f, cx, cy, width, height, pose, PoseConvention::OpenCV));
    RenderedFrame frame = renderer.renderOutputs(scene, {.depth = true, .objectIds = true});
    const std::string name = std::to_string(1000 + i).substr(1);
    writePng(out + "/" + name + "_rgb.png", frame.image);
    writeNpy(out + "/" + name + "_depth.npy", frame.depth, width, height);
    for (size_t p = 0; p < frame.objectIds.size(); ++p)
      for (int k = 0; k < 3; ++k) frame.image.rgb[3 * p + k] = frame.objectIds[p] >= 0 ? 255 : 0;
    writePng(out + "/" + name + "_mask.png", frame.image);
    cameras << (i ? ", " : "") << "{\"file\": \"" << name << "_rgb.png\", \"camera_to_world\": [";
    for (int row = 0; row < 4; ++row)
      cameras << (row ? ", [" : "[") << pose[4 * row] << ", " << pose[4 * row + 1] << ", " << pose[4 * row + 2] << ", "
              << pose[4 * row + 3] << "]";
    cameras << "]}";
  }
  cameras << "]}\n";
  std::printf("%d views of %s in %s\n", views, argv[1], out.c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 2;
}
