// bind_renderer.cpp — phongvk.Renderer, diff and devices for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindRenderer(py::module_& m) {
  py::class_<Renderer>(m, "Renderer", R"(Renders scenes on one backend.

backend: "gpu" (the Vulkan compute port, default), "cpu" (the reference) or "graphics" (the Vulkan
    graphics-pipeline baseline). "gpu" and "cpu" give the same bytes; pick by speed. On a
    machine with a GPU, "gpu". On a CPU-only machine (lavapipe), "cpu" is about as fast for
    small models (a 1,280-triangle sphere at 640x480 from a Python loop: 2.4-3.0 ms a frame
    against 2.5-2.6 in two runs) and quicker for single stills (a cold process 0.12-0.14 s
    against 0.26-0.28), "gpu" for many triangles or large images (1.3M triangles at 1920x1080:
    79-89 ms against 259-287; the paper's scenes at 1385x923: 7-10 ms against 18-38);
    bench/peers.py measures it on the machine at hand.
device: a Vulkan device index (see devices()); None for the best usable one.
validate: turn the Vulkan validation layers on.

A renderer keeps what it uploaded: rendering a scene with the same geometry as the last one (another
camera, size, lights or materials, another frame of an orbit) builds and uploads no mesh again
(stats["scene_builds"] counts the builds). The GIL is released while rendering, so renderers in
other threads go on; one renderer used from several threads renders one frame at a time.)")
      .def(py::init([](const std::string& backend, std::optional<int> device, bool validate) {
             return std::make_unique<Renderer>(rendererOptions(backend, device, validate));
           }),
           py::arg("backend") = "gpu", py::arg("device") = py::none(), py::arg("validate") = false)
      .def("__repr__",
           [](const Renderer& r) {
             return "<phongvk.Renderer " + std::string(backendName(r.backend())) + " on " + r.deviceName() + ">";
           })
      .def(
          "render",
          [](Renderer& r, const Scene& scene, std::optional<int> width, std::optional<int> height) {
            return imageArray(released(r, scene, width, height, &Renderer::render));
          },
          py::arg("scene"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          "One frame of `scene` as a C-contiguous uint8 array of shape (height, width, 3), row 0 at the top.")
      .def(
          "render_outputs",
          [](Renderer& r, const Scene& scene, const std::vector<std::string>& names, std::optional<int> width,
             std::optional<int> height) {
            return outputsDict(renderedFrame(r, scene, width, height, outputsNamed(names)), names);
          },
          py::arg("scene"), py::arg("outputs"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          "render(scene, outputs=...) without the package's Image view: a dict of arrays by name.")
      .def(
          "render_visibility",
          [](Renderer& r, const Scene& scene, std::optional<int> width, std::optional<int> height) {
            RenderedFrame frame = renderedFrame(r, scene, width, height, Outputs{.depth = true, .triangleIds = true});
            const py::ssize_t h = frame.image.height, w = frame.image.width;
            std::vector<uint32_t> triangle(frame.triangleIds.size());
            std::memcpy(triangle.data(), frame.triangleIds.data(), triangle.size() * sizeof(uint32_t));  // -1: NO_TRIANGLE
            return py::make_tuple(imageArray(std::move(frame.image)), ownedArray(std::move(triangle), {h, w}),
                                  ownedArray(std::move(frame.depth), {h, w}));
          },
          py::arg("scene"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          R"(One frame with its visibility buffer: (image, triangle, depth).

triangle: (height, width) uint32 array, the winning triangle's index in the scene (objects in order,
    each object's triangles in order), NO_TRIANGLE where nothing covers the pixel.
depth: (height, width) float32 array, the winning fragment's depth along the camera's axis in
    metres, inf where nothing covers it.
With samples per pixel, both are the pixel's nearest sample's. The gpu and cpu backends give the
same buffers; the graphics backend has none (ValueError).)")
      .def(
          "diff",
          [](Renderer& r, const Scene& scene) {
            DiffResult result;
            {
              py::gil_scoped_release release;
              result = diff(scene, r);
            }
            return diffDict(result);
          },
          py::arg("scene"),
          "`scene` rendered by the reference and by this renderer, compared as phongvk.diff() does (a dict "
          "with the numbers `phongvk diff` prints and its text as \"report\").")
      .def_property_readonly("backend", [](const Renderer& r) { return backendName(r.backend()); },
                             "The backend's name.")
      .def("close", &Renderer::close,
           "Frees the renderer's device, buffers and pipelines now (also at the end of a `with` block); "
           "calls after it raise ArgumentError.")
      .def_property_readonly("device_name", &Renderer::deviceName,
                             "The Vulkan device's name, or 'cpu (reference)'.")
      .def_property_readonly("stats", [](const Renderer& r) { return statsDict(r.stats()); },
                             "What the renderer has done: scene_builds, frames_rendered, frames_shaded, "
                             "frames_repeated, triangles, build_ms, texture_bytes (the last scene's textures), device_bytes "
                             "(device memory the renderer's buffers hold; 0 for the reference), validation_messages; and where its "
                             "start-up went (Vulkan backends; 0 for the reference): startup_vulkan_ms "
                             "(instance and device), startup_probe_ms (the float probe; 0 when cached), "
                             "startup_pipelines_ms, first_frame_ms (the first frame on the device: on "
                             "lavapipe with an empty Mesa shader cache, mostly code generation); notice "
                             "(a sentence on what a user may not expect of the last scene's picture, such as "
                             "a fitted camera that sees only the back of every triangle; empty when none).")
      .def_property_readonly("notice", [](const Renderer& r) { return r.stats().notice; },
                             "stats['notice'] alone: Renderer.render warns with it (phongvk.NoticeWarning).");

  m.def(
      "diff",
      [](const Scene& scene, std::optional<int> device) {
        DiffResult result;
        {
          py::gil_scoped_release release;
          result = diff(scene, rendererOptions("gpu", device, false));
        }
        return diffDict(result);
      },
      py::arg("scene"), py::arg("device") = py::none(),
      R"(Renders `scene` with the reference and the compute port and compares them, pixel by pixel and key
by key: the numbers `phongvk diff` prints, as a dict (width, height, pixels, differing, max_abs,
mean_abs, psnr, triangle_mismatch, identical_fraction, device), and its text as "report".)");

  m.def("devices", [] {
    py::list list;
    for (const DeviceInfo& info : listDevices()) list.append(deviceDict(info));
    return list;
  }, "The Vulkan devices, each a dict: index, name, type, api_version, usable, missing (what it lacks).");
}

}  // namespace phongvk::python
