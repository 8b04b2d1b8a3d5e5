// bind_render_settings.cpp — phongvk.RenderSettings for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindRenderSettings(py::module_& m) {
  const RenderSettings settings;
  py::class_<RenderSettings>(m, "RenderSettings", R"(How a scene is rendered: its scene file's "render" options
and background. shading: "gouraud" (lit at the vertices), "flat" (once per triangle) or "phong" (at
every pixel); specular: "phong" or "blinn" (the highlight's base); interpolation: "perspective" or
"screen"; samples per pixel: 1, 4, 9 or 16; background: RGB in [0, 1]; texture_filter: "bilinear" or
"nearest" (how a model's base-colour texture is sampled); point_size and line_width: points' side and
lines' width in pixels, above 0 and at most 64 (default 1). The defaults are the scene file's. A name that is none of the choices raises SceneError at once; the rest is checked when a
scene takes the settings (Scene.render_settings, with_render), like a scene file's "render".)")
      .def(py::init([](const std::string& shading, const std::string& specular, const std::string& interpolation,
                       int samples, Vec3 background, const std::string& textureFilter, double pointSize, double lineWidth) {
             return RenderSettings{parseShading(shading), parseSpecular(specular), parseInterpolation(interpolation),
                                   samples, background, parseTextureFilter(textureFilter), pointSize, lineWidth};
           }),
           py::kw_only(), py::arg("shading") = shadingName(settings.shading),
           py::arg("specular") = specularName(settings.specular),
           py::arg("interpolation") = interpolationName(settings.interpolation), py::arg("samples") = settings.samples,
           py::arg("background") = settings.background, py::arg("texture_filter") = textureFilterName(settings.textureFilter),
           py::arg("point_size") = settings.pointSize, py::arg("line_width") = settings.lineWidth)
      .def_property(
          "shading", [](const RenderSettings& s) { return shadingName(s.shading); },
          [](RenderSettings& s, const std::string& name) { s.shading = parseShading(name); },
          "\"gouraud\", \"flat\" or \"phong\".")
      .def_property(
          "specular", [](const RenderSettings& s) { return specularName(s.specular); },
          [](RenderSettings& s, const std::string& name) { s.specular = parseSpecular(name); }, "\"phong\" or \"blinn\".")
      .def_property(
          "interpolation", [](const RenderSettings& s) { return interpolationName(s.interpolation); },
          [](RenderSettings& s, const std::string& name) { s.interpolation = parseInterpolation(name); },
          "\"perspective\" or \"screen\".")
      .def_property(
          "texture_filter", [](const RenderSettings& s) { return textureFilterName(s.textureFilter); },
          [](RenderSettings& s, const std::string& name) { s.textureFilter = parseTextureFilter(name); },
          "\"bilinear\" or \"nearest\".")
      .def_readwrite("samples", &RenderSettings::samples, "Samples per pixel: 1, 4, 9 or 16 (a regular grid).")
      .def_readwrite("background", &RenderSettings::background, "RGB in [0, 1] where nothing is drawn.")
      .def_readwrite("point_size", &RenderSettings::pointSize, "Points' side in pixels (0 < size <= 64).")
      .def_readwrite("line_width", &RenderSettings::lineWidth, "Lines' width in pixels (0 < width <= 64).")
      .def("__eq__", [](const RenderSettings& a, const RenderSettings& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const RenderSettings& s) {
        return std::string("phongvk.RenderSettings(shading='") + shadingName(s.shading) + "', specular='" +
               specularName(s.specular) + "', interpolation='" + interpolationName(s.interpolation) +
               "', samples=" + std::to_string(s.samples) + ", background=" + vec3Text(s.background) +
               ", texture_filter='" + textureFilterName(s.textureFilter) + "', point_size=" + floatText(s.pointSize) +
               ", line_width=" + floatText(s.lineWidth) + ")";
      });
}

}  // namespace phongvk::python
