// render_outputs.cpp — --rgba, --depth and --ids of `phongvk render`. A 16-bit PNG holds a depth in
// millimetres (0 where empty), as the TUM and NYU RGB-D datasets store theirs, and an object id as
// index + 1 (0 where empty); a .npy file holds the renderer's own values.
#include "cli/render_outputs.h"

#include "cli/cli_support.h"
#include "phongvk/npy.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace phongvk::cli {
namespace {

constexpr uint16_t GREY16_MAX = 65535;
constexpr size_t MAX_PNG_OBJECTS = GREY16_MAX - 1;  // ids 1..65535 are index + 1

enum class FileKind { None, Png, Npy };

// The kind of a --depth or --ids file, from its extension.
FileKind fileKind(const std::string& path, const char* option) {
  if (path.empty()) return FileKind::None;
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".png") return FileKind::Png;
  if (extension == ".npy") return FileKind::Npy;
  throw UsageError(std::string(option) + " " + path + ": the file must end in .png (16-bit grey) or .npy (NumPy)");
}

// Metres to millimetres, rounded to the nearest, 0 where empty (+inf), at most 65535.
uint16_t depthMillimetres(float metres) {
  if (!std::isfinite(metres)) return 0;
  return uint16_t(std::min(std::round(double(metres) * 1000.0), double(GREY16_MAX)));
}

ImageGrey16 grey16(const RenderedFrame& frame, const auto& values, const auto& sample) {
  ImageGrey16 image{frame.image.width, frame.image.height, std::vector<uint16_t>(values.size())};
  std::transform(values.begin(), values.end(), image.grey.begin(), sample);
  return image;
}

ImageRGBA withAlpha(const RenderedFrame& frame) {
  ImageRGBA image{frame.image.width, frame.image.height, std::vector<uint8_t>(frame.alpha.size() * 4)};
  for (size_t i = 0; i < frame.alpha.size(); ++i) {
    std::copy_n(&frame.image.rgb[i * 3], 3, &image.rgba[i * 4]);
    image.rgba[i * 4 + 3] = frame.alpha[i];
  }
  return image;
}

void writeDepth(const RenderOptions& options, const RenderedFrame& frame) {
  const int w = frame.image.width, h = frame.image.height;
  if (fileKind(options.depth, "--depth") == FileKind::Npy) return writeNpy(options.depth, frame.depth, w, h);
  writePng(options.depth, grey16(frame, frame.depth, depthMillimetres), options.pngLevel);
}

void writeIds(const RenderOptions& options, const RenderedFrame& frame) {
  const int w = frame.image.width, h = frame.image.height;
  if (fileKind(options.ids, "--ids") == FileKind::Npy) return writeNpy(options.ids, frame.objectIds, w, h);
  writePng(options.ids, grey16(frame, frame.objectIds, [](int32_t id) { return uint16_t(id + 1); }), options.pngLevel);
}

}  // namespace

Outputs outputsAsked(const RenderOptions& options) {
  Outputs outputs;
  outputs.alpha = options.rgba;
  outputs.depth = fileKind(options.depth, "--depth") != FileKind::None;
  outputs.objectIds = fileKind(options.ids, "--ids") != FileKind::None;
  if (options.mpi && (outputs.alpha || outputs.depth || outputs.objectIds)) {
    throw UsageError("--rgba, --depth and --ids are not available with --mpi (each process holds a share of the "
                     "scene's triangles): render without --mpi for them");
  }
  return outputs;
}

void checkOutputFiles(const RenderOptions& options, const Scene& scene) {
  if (fileKind(options.ids, "--ids") == FileKind::Png && scene.objectCount() > MAX_PNG_OBJECTS) {
    throw UsageError("--ids " + options.ids + ": a 16-bit PNG holds at most " + std::to_string(MAX_PNG_OBJECTS) +
                     " objects' ids, the scene has " + std::to_string(scene.objectCount()) + ": write .npy instead");
  }
  for (const std::string& path : {options.depth, options.ids}) {
    if (!path.empty()) checkWritable(path);
  }
}

void writeRenderedFiles(const RenderOptions& options, const RenderedFrame& frame) {
  if (options.rgba) {
    writePng(options.output, withAlpha(frame), options.pngLevel);
  } else {
    writePng(options.output, frame.image, options.pngLevel);
  }
  if (!options.depth.empty()) writeDepth(options, frame);
  if (!options.ids.empty()) writeIds(options, frame);
}

}  // namespace phongvk::cli
