// scene_textures.cpp — see scene_textures.h.
#include "scene/scene_textures.h"

#include "image/texture_decode.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>

namespace phongvk {

namespace {

// What a cached texture was decoded from: the source (an absolute path or a data URI) and, for a
// file, its size and modification time then.
struct SourceVersion {
  std::string source;
  int64_t bytes = -1;
  int64_t modified = 0;
  bool operator<(const SourceVersion& o) const {
    return std::tie(source, bytes, modified) < std::tie(o.source, o.bytes, o.modified);
  }
};

SourceVersion versionOf(const std::string& source) {
  SourceVersion v{source};
  struct stat s;
  if (source.rfind("data:", 0) != 0 && ::stat(source.c_str(), &s) == 0) {
    v.bytes = int64_t(s.st_size);
    v.modified = int64_t(s.st_mtim.tv_sec) * 1000000000 + s.st_mtim.tv_nsec;
  }
  return v;
}

}  // namespace

std::string textureSourceOf(const std::string& source, const std::string& baseDir) {
  if (source.rfind("data:", 0) == 0 || source.empty()) return source;
  const std::filesystem::path path(source);
  return path.is_absolute() || baseDir.empty() ? source : (std::filesystem::path(baseDir) / path).string();
}

std::shared_ptr<const TextureImage> sceneTexture(const std::string& source, const std::string& baseDir,
                                                 const std::string& what) {
  static std::mutex lock;
  static std::map<SourceVersion, std::weak_ptr<const TextureImage>> decoded;
  const SourceVersion version = versionOf(textureSourceOf(source, baseDir));
  {
    const std::lock_guard<std::mutex> held(lock);
    if (auto texture = decoded[version].lock()) return texture;
  }
  auto texture = std::make_shared<const TextureImage>(readTextureSource(version.source, what));
  const std::lock_guard<std::mutex> held(lock);
  std::erase_if(decoded, [](const auto& entry) { return entry.second.expired(); });
  decoded[version] = texture;
  return texture;
}

}  // namespace phongvk
