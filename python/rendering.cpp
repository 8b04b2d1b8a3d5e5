// rendering.cpp — rendering: sizes, outputs, stats, diffs and devices as Python values (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

Scene sized(const Scene& scene, std::optional<int> width, std::optional<int> height) {
  if (width.has_value() != height.has_value()) throw py::value_error("width and height go together");
  return width ? scene.withImageSize(*width, *height) : scene;
}

RenderedFrame renderedFrame(Renderer& renderer, const Scene& scene, std::optional<int> width, std::optional<int> height,
                            const Outputs& outputs) {
  const Scene s = sized(scene, width, height);
  py::gil_scoped_release release;
  return renderer.renderOutputs(s, outputs);
}

Outputs outputsNamed(const std::vector<std::string>& names) {
  Outputs outputs;
  for (auto name = names.begin(); name != names.end(); ++name) {
    if (std::find(names.begin(), name, *name) != name)
      throw ArgumentError("outputs: '" + *name + "' is asked for more than once");
  }
  for (const std::string& name : names) {
    if (name == "alpha" || name == "rgba") outputs.alpha = true;
    else if (name == "depth") outputs.depth = true;
    else if (name == "object_id") outputs.objectIds = true;
    else if (name == "triangle_id") outputs.triangleIds = true;
    else if (name == "normal") outputs.normals = true;
    else if (name == "lights") outputs.lights = true;
    else if (name != "color")
      throw ArgumentError("outputs: unknown output '" + name +
                          "' (color, rgba, alpha, depth, object_id, triangle_id, normal, lights)");
  }
  return outputs;
}

py::dict outputsDict(RenderedFrame&& frame, const std::vector<std::string>& names) {
  const py::ssize_t h = frame.image.height, w = frame.image.width;
  const size_t pixels = size_t(h) * size_t(w);
  py::dict d;
  for (const std::string& name : names) {
    if (name == "rgba") {
      std::vector<uint8_t> rgba(pixels * 4);
      for (size_t i = 0; i < pixels; ++i) {
        std::memcpy(&rgba[4 * i], &frame.image.rgb[3 * i], 3);
        rgba[4 * i + 3] = frame.alpha[i];
      }
      d["rgba"] = ownedArray(std::move(rgba), {h, w, 4});
    } else if (name == "alpha") {
      d["alpha"] = ownedArray(std::vector<uint8_t>(frame.alpha), {h, w});
    } else if (name == "depth") {
      d["depth"] = ownedArray(std::move(frame.depth), {h, w});
    } else if (name == "object_id") {
      d["object_id"] = ownedArray(std::move(frame.objectIds), {h, w});
    } else if (name == "triangle_id") {
      d["triangle_id"] = ownedArray(std::move(frame.triangleIds), {h, w});
    } else if (name == "normal") {
      d["normal"] = ownedArray(std::move(frame.normals), {h, w, 3});
    } else if (name == "lights") {
      d["lights"] = ownedArray(std::move(frame.lights), {h, w});
    }
  }
  // The colour last: rgba above copied from the image this moves.
  if (std::find(names.begin(), names.end(), "color") != names.end()) d["color"] = imageArray(std::move(frame.image));
  return d;
}

py::dict statsDict(const RendererStats& s) {
  py::dict d;
  d["scene_builds"] = s.sceneBuilds;
  d["frames_rendered"] = s.framesRendered;
  d["frames_shaded"] = s.framesShaded;
  d["frames_repeated"] = s.framesRepeated;
  d["triangles"] = s.triangles;
  d["lines"] = s.lines;
  d["points"] = s.points;
  d["lights"] = s.lights;
  d["build_ms"] = s.buildMs;
  d["texture_bytes"] = s.textureBytes;
  d["device_bytes"] = s.deviceBytes;
  d["validation_messages"] = s.validationMessages;
  d["startup_vulkan_ms"] = s.contextMs;
  d["startup_probe_ms"] = s.probeMs;
  d["startup_pipelines_ms"] = s.pipelinesMs;
  d["first_frame_ms"] = s.firstFrameMs;
  d["notice"] = s.notice;
  return d;
}

py::dict diffDict(const DiffResult& r) {
  const DiffStats& s = r.stats;
  py::dict d;
  d["width"] = s.width;
  d["height"] = s.height;
  d["pixels"] = s.pixels;
  d["differing"] = s.differing;
  d["max_abs"] = py::make_tuple(s.maxAbs[0], s.maxAbs[1], s.maxAbs[2]);
  d["mean_abs"] = py::make_tuple(s.meanAbs[0], s.meanAbs[1], s.meanAbs[2]);
  d["psnr"] = s.psnr;
  d["triangle_mismatch"] = s.triangleMismatch;
  d["identical_fraction"] = s.identicalFraction();
  d["device"] = r.deviceName;
  d["report"] = formatDiff(s);
  return d;
}

py::dict deviceDict(const DeviceInfo& info) {
  py::dict d;
  d["index"] = info.index;
  d["name"] = info.name;
  d["type"] = info.type;
  d["api_version"] = info.apiVersion;
  d["usable"] = info.suitable;
  d["missing"] = info.missing;
  d["keys"] = keyPathWords(info);  // "64-bit atomics" or "32-bit atomics, two passes (...)"
  return d;
}

RendererOptions rendererOptions(const std::string& backend, std::optional<int> device, bool validate) {
  return {parseBackend(backend), device.value_or(-1), validate};
}

}  // namespace phongvk::python
