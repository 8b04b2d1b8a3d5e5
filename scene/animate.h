// animate.h — scene sequences: a scene file's "animate" block and the scenes it makes, one per
// frame, each validated exactly like a scene file.
//
//   "animate": {"frames": 120, "tracks": [
//     {"path": "camera.position", "expression": ["5*cos(2*pi*i/n)", "5*sin(2*pi*i/n)", 2.5]},
//     {"path": "objects[0].material.ks", "values": [0, 0.5, 1]}]}
//
// A track's `path` points into the scene JSON (keys joined by '.', array elements as [k]); every
// part but the last must exist, and the last may name a key the object does not have yet (a value
// left to its default). Per frame a track gives either `values[i]` (one JSON value per frame, of
// any type the scene allows there) or its `expression` evaluated at that frame (expression.h: a
// string, or an array mixing numbers and strings for a vector). Tracks apply in order, so a later
// track overrides an earlier one's value at the same path. A file without "animate" is a sequence
// of one frame.
#pragma once

#include "scene/scene.h"
#include "scene/model_scene.h"
#include "scene/scene_json.h"

#include <string>
#include <vector>

namespace phongvk {

// One step of a track path: an object key or an array index.
struct PathStep {
  std::string key;   // empty for an index
  size_t index = 0;
  bool isIndex() const { return key.empty(); }
};

struct Track {
  std::string path;                     // as written, "objects[0].material.ks"
  std::vector<PathStep> steps;
  std::string where;                    // its JSON path, "animate.tracks[1]", for messages
  std::vector<scenejson::Json> frames;  // the value at each frame (expressions evaluated at load)
  bool geometry = false;                // changes a mesh: under objects[k], not its material
};

// The steps of a track path, e.g. "objects[0].material.ks" -> objects, [0], material, ks.
// Throws SceneError at `node` (the path's JSON node) for a malformed path.
std::vector<PathStep> parseTrackPath(const scenejson::Node& node);

class SceneSequence {
 public:
  // Reads a scene file, or a model file alone (model_scene.h) shown as `model` says; errors as
  // loadSceneSpec's, and ArgumentError for a `model` given with a scene file.
  static SceneSequence load(const std::string& path, const ModelView& model = {});
  // `json` is the whole scene file; `path` names it in messages and `baseDir` resolves its
  // relative files. Validates the "animate" block, evaluating every expression at every frame
  // (so a NaN at frame 17 is an error before anything is rendered), and that every track path
  // exists. Frames themselves are validated by frame(). Throws SceneError.
  // With `objectsLater` a frame may have no objects yet (scene.h parseSceneSpec).
  SceneSequence(scenejson::Json json, std::string path, std::string baseDir, bool objectsLater = false);

  int frameCount() const { return frames_; }
  const std::string& path() const { return path_; }
  const std::vector<Track>& tracks() const { return tracks_; }

  // The scene JSON at `frame` (0 <= frame < frameCount()), without the "animate" block.
  scenejson::Json frameJson(int frame) const;

  // The scene at `frame`: frameJson read by the scene file's own readers, so it is checked like any scene file.
  // Messages name the frame: "a.json: frame 17: objects[0].material.ks: must be >= 0, got -1".
  SceneSpec frame(int frame) const;

  // True when some track changes geometry between frames a and b, so meshes must be rebuilt.
  bool geometryDiffers(int a, int b) const;

 private:
  scenejson::Json base_;  // the file's JSON without "animate"
  std::string path_;
  std::string baseDir_;
  int frames_ = 1;
  bool animated_ = false;  // the file has an "animate" block (its messages then name the frame)
  bool objectsLater_ = false;
  bool modelAlone_ = false;  // a mesh file given alone (model_scene.h): its frames say so
  std::vector<Track> tracks_;
};

}  // namespace phongvk
