// render_scene — renders a phongvk scene file to PNG through the installed library's public API.
//
//   render_scene SCENE.json OUT.png [gpu|cpu]
#include <phongvk/phongvk.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: render_scene SCENE.json OUT.png [gpu|cpu]\n");
    return 2;
  }
  try {
    const phongvk::Scene scene = phongvk::loadScene(argv[1]);
    const phongvk::Backend backend = argc == 4 ? phongvk::parseBackend(argv[3]) : phongvk::Backend::Gpu;
    phongvk::Renderer renderer(backend);
    const phongvk::Image image = renderer.render(scene);
    phongvk::writePng(argv[2], image);
    std::printf("%s: %dx%d on %s, phongvk %s (%s)\n", argv[1], image.width, image.height,
                renderer.deviceName().c_str(), phongvk::version(), phongvk::revision());
    return 0;
  } catch (const phongvk::SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 4;
  }
}
