// scene_textures.cpp — see scene_textures.h.
#include "scene/scene_textures.h"

#include "image/texture_decode.h"
#include "scene/scene.h"

#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>

namespace phongvk {

namespace {

// What a cached texture was decoded from: the source (an absolute path or a data URI) and, for a
// file, its version then.
struct SourceVersion {
  std::string source;
  FileVersion file;
  bool operator<(const SourceVersion& o) const {
    return std::tie(source, file.bytes, file.modified) < std::tie(o.source, o.file.bytes, o.file.modified);
  }
};

SourceVersion versionOf(const std::string& source) {
  return {source, source.rfind("data:", 0) == 0 ? FileVersion{} : fileVersion(source)};
}

}  // namespace

std::string textureSourceOf(const std::string& source, const std::string& baseDir) {
  if (source.rfind("data:", 0) == 0) return source;
  return (std::filesystem::path(baseDir) / source).string();  // an absolute source replaces baseDir
}

std::shared_ptr<const TextureImage> sceneTexture(const std::string& source, const std::string& baseDir) {
  static std::mutex lock;
  static std::map<SourceVersion, std::weak_ptr<const TextureImage>> decoded;
  const SourceVersion version = versionOf(textureSourceOf(source, baseDir));
  {
    const std::lock_guard<std::mutex> held(lock);
    if (auto texture = decoded[version].lock()) return texture;
  }
  const std::string what = source.rfind("data:", 0) == 0 ? "the data URI" : "'" + source + "'";
  auto texture = std::make_shared<const TextureImage>(readTextureSource(version.source, what));
  const std::lock_guard<std::mutex> held(lock);
  std::erase_if(decoded, [](const auto& entry) { return entry.second.expired(); });
  decoded[version] = texture;
  return texture;
}

}  // namespace phongvk
