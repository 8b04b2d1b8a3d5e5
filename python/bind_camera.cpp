// bind_camera.cpp — phongvk.Camera for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindCamera(py::module_& m) {
  py::class_<Camera>(m, "Camera", R"(A camera: position, look_at, up (world coordinates, z up by
default), and its view: fov (vertical, degrees), or intrinsics (fx, fy, cx, cy in pixels) of a
pinhole camera, or ortho_height (metres from the image's top to its bottom) of an orthographic
one; width x height (0 x 0: the scene's own size), near and far.
Camera.from_pose and Camera.from_intrinsics make one from a camera-to-world matrix. Assigned to
Scene.camera, it is checked like a scene file's "camera".)")
      .def(py::init([](Vec3 position, Vec3 lookAt, Vec3 up, double fov, int width, int height, double nearPlane,
                       double farPlane, std::optional<std::array<double, 4>> k, std::optional<double> orthoHeight) {
             Camera camera{position, lookAt, up, fov, width, height, nearPlane, farPlane};
             if (k) camera.intrinsics = Intrinsics{(*k)[0], (*k)[1], (*k)[2], (*k)[3]};
             camera.orthoHeight = orthoHeight;
             return camera;
           }),
           py::kw_only(), py::arg("position") = Camera{}.position, py::arg("look_at") = Camera{}.lookAt,
           py::arg("up") = Camera{}.up, py::arg("fov") = Camera{}.fov, py::arg("width") = 0, py::arg("height") = 0,
           py::arg("near") = Camera{}.nearPlane, py::arg("far") = Camera{}.farPlane, py::arg("intrinsics") = py::none(),
           py::arg("ortho_height") = py::none())
      .def_readwrite("position", &Camera::position)
      .def_readwrite("look_at", &Camera::lookAt)
      .def_readwrite("up", &Camera::up)
      .def_readwrite("fov", &Camera::fov)
      .def_readwrite("width", &Camera::width)
      .def_readwrite("height", &Camera::height)
      .def_readwrite("near", &Camera::nearPlane)
      .def_readwrite("far", &Camera::farPlane)
      .def_property(
          "intrinsics",
          [](const Camera& c) -> py::object {
            if (!c.intrinsics) return py::none();
            return py::make_tuple(c.intrinsics->fx, c.intrinsics->fy, c.intrinsics->cx, c.intrinsics->cy);
          },
          [](Camera& c, const py::object& value) {
            if (value.is_none()) return c.intrinsics.reset();
            const auto k = value.cast<std::array<double, 4>>();
            c.intrinsics = Intrinsics{k[0], k[1], k[2], k[3]};
          },
          R"((fx, fy, cx, cy) in pixels, OpenCV's convention (pixel centres at integer coordinates), or
None: the field of view is fov. With intrinsics the camera needs a width and height.)")
      .def_readwrite("ortho_height", &Camera::orthoHeight,
                     R"(Metres the image spans from top to bottom (and ortho_height * width / height
across) for an orthographic camera, whose pixels all look along the view direction; None for a
perspective one. An orthographic camera needs a width and height, and no intrinsics.)")
      .def_static(
          "from_pose",
          [](const py::object& pose, const std::string& conventionName, double fov, int width, int height,
             std::optional<double> orthoHeight) {
            Camera camera = cameraFromPose(matrix4(pose, "pose"), convention(conventionName), fov, width, height);
            camera.orthoHeight = orthoHeight;
            return camera;
          },
          py::arg("pose"), py::kw_only(), py::arg("convention") = "opengl", py::arg("fov") = 60.0,
          py::arg("width") = 0, py::arg("height") = 0, py::arg("ortho_height") = py::none(),
          R"(The camera a (4, 4) camera-to-world pose describes. convention: "opengl" (the camera looks
down its -z, y up: Blender, three.js, NeRF) or "opencv" (looks down +z, y down: COLMAP, most
datasets). A pose whose rotation block is not a rotation raises ValueError. ortho_height (metres
from the image's top to its bottom) makes it an orthographic camera, fov then unused.)")
      .def_static(
          "from_intrinsics",
          [](double fx, double fy, double cx, double cy, int width, int height, const py::object& pose,
             const std::string& conventionName) {
            return cameraFromIntrinsics(fx, fy, cx, cy, width, height, matrix4(pose, "pose"), convention(conventionName));
          },
          py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("width"), py::arg("height"),
          py::arg("pose") = py::none(), py::arg("convention") = "opengl",
          R"(The camera of pinhole intrinsics (pixels, OpenCV's convention: pixel centres at integer
coordinates, so the centre is ((width - 1) / 2, (height - 1) / 2)) and a (4, 4) camera-to-world pose
(identity when None) in the convention every pose-taking call defaults to, "opengl" (as from_pose;
datasets with intrinsics often give "opencv" poses: say so). fx and fy may differ; the principal point (cx, cy) may lie off centre, or
outside the image within 16384 pixels of it. A focal length that is not positive raises ValueError.)")
      .def("__eq__", [](const Camera& a, const Camera& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const Camera& c) {
        return "phongvk.Camera(position=" + vec3Text(c.position) + ", look_at=" + vec3Text(c.lookAt) + ", up=" +
               vec3Text(c.up) + fieldOfViewText(c) + ", width=" + std::to_string(c.width) +
               ", height=" + std::to_string(c.height) + ")";
      });
}

}  // namespace phongvk::python
