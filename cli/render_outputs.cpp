// render_outputs.cpp — --rgba, --depth, --ids, --normals and --lights of `phongvk render`. A 16-bit
// PNG holds a depth in millimetres (0 where empty), as the TUM and NYU RGB-D datasets store theirs,
// an object id as index + 1 and a count of lights as count + 1 (0 where empty); an 8-bit RGB PNG holds a normal as normal maps do,
// (n + 1) / 2 * 255 rounded (0, 0, 0 where empty); a .npy file holds the renderer's own values.
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

// The kind of a --depth, --ids or --normals file, from its extension; `png` says what its PNG holds.
FileKind fileKind(const std::string& path, const char* option, const char* png = "16-bit grey") {
  if (path.empty()) return FileKind::None;
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".png") return FileKind::Png;
  if (extension == ".npy") return FileKind::Npy;
  throw UsageError(std::string(option) + " " + path + ": the file must end in .png (" + png + ") or .npy (NumPy)");
}

FileKind normalsKind(const RenderOptions& options) { return fileKind(options.normals, "--normals", "8-bit RGB"); }

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

// A normal's component in [-1, 1] as a normal map's byte: (n + 1) / 2 * 255, rounded to the nearest.
uint8_t normalByte(float n) {
  return uint8_t(std::clamp(std::floor((double(n) * 0.5 + 0.5) * 255.0 + 0.5), 0.0, 255.0));
}

// The normals as a normal map, 0, 0, 0 where empty (no unit normal encodes as black).
Image normalMap(const RenderedFrame& frame) {
  Image image(frame.image.width, frame.image.height);
  for (size_t i = 0; i < frame.normals.size(); i += 3) {
    if (frame.normals[i] == 0 && frame.normals[i + 1] == 0 && frame.normals[i + 2] == 0) continue;
    for (size_t c = i; c < i + 3; ++c) image.rgb[c] = normalByte(frame.normals[c]);
  }
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

void writeLights(const RenderOptions& options, const RenderedFrame& frame) {
  const int w = frame.image.width, h = frame.image.height;
  if (fileKind(options.lights, "--lights") == FileKind::Npy) return writeNpy(options.lights, frame.lights, w, h);
  writePng(options.lights, grey16(frame, frame.lights, [](int32_t n) { return uint16_t(n + 1); }), options.pngLevel);
}

void writeNormals(const RenderOptions& options, const RenderedFrame& frame) {
  const int w = frame.image.width, h = frame.image.height;
  if (normalsKind(options) == FileKind::Npy) return writeNpy(options.normals, frame.normals, w, h, 3);
  writePng(options.normals, normalMap(frame), options.pngLevel);
}

// Each file written names a file of its own: two options naming one file would leave only the
// last written, with an exit status of 0. Names are compared as the files they reach (x.png,
// ./x.png and a link to it are one file); standard output ('-') is no file.
void checkDistinctFiles(const RenderOptions& options) {
  const std::pair<const char*, const std::string*> files[] = {
      {"-o", &options.output}, {"--depth", &options.depth}, {"--ids", &options.ids}, {"--normals", &options.normals},
      {"--lights", &options.lights}};
  std::vector<std::pair<std::filesystem::path, const char*>> seen;
  for (const auto& [option, path] : files) {
    if (path->empty() || *path == "-") continue;
    std::error_code error;
    std::filesystem::path file = std::filesystem::weakly_canonical(*path, error);
    if (error) file = std::filesystem::absolute(*path).lexically_normal();
    for (const auto& [other, otherOption] : seen) {
      if (other == file)
        throw UsageError(std::string(option) + " " + *path + ": the same file as " + otherOption + "; each output needs a file of its own");
    }
    seen.push_back({file, option});
  }
}

}  // namespace

Outputs outputsAsked(const RenderOptions& options) {
  Outputs outputs;
  outputs.alpha = options.rgba;
  outputs.depth = fileKind(options.depth, "--depth") != FileKind::None;
  outputs.objectIds = fileKind(options.ids, "--ids") != FileKind::None;
  outputs.normals = normalsKind(options) != FileKind::None;
  outputs.lights = fileKind(options.lights, "--lights") != FileKind::None;
  return outputs;
}

void checkOutputFiles(const RenderOptions& options, const Scene& scene) {
  checkDistinctFiles(options);
  if (fileKind(options.ids, "--ids") == FileKind::Png && scene.objectCount() > MAX_PNG_OBJECTS) {
    throw UsageError("--ids " + options.ids + ": a 16-bit PNG holds at most " + std::to_string(MAX_PNG_OBJECTS) +
                     " objects' ids, the scene has " + std::to_string(scene.objectCount()) + ": write .npy instead");
  }
  for (const std::string& path : {options.depth, options.ids, options.normals, options.lights}) {
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
  if (!options.normals.empty()) writeNormals(options, frame);
  if (!options.lights.empty()) writeLights(options, frame);
}

}  // namespace phongvk::cli
