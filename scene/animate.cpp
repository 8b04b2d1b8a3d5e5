// animate.cpp — the "animate" block's rules and applying tracks at the JSON level. The scene's own
// rules are not repeated here: each frame's JSON goes through the scene file's readers.
#include "scene/animate.h"

#include "scene/model_scene.h"

#include "scene/expression.h"
#include "scene/scene_sections.h"

#include <cassert>
#include <charconv>
#include <cmath>
#include <filesystem>

namespace phongvk {
namespace {

using namespace scenejson;

const Keys kAnimateKeys = {"frames", "tracks"};
const Keys kTrackKeys = {"path", "values", "expression"};

// An hour at 24 frames per second, with room to spare; every track holds one value per frame.
constexpr int kMaxFrames = 100000;

// "[3]" or ".key" ("key" first), to show a prefix of a path in messages.
std::string stepText(const PathStep& step, bool first) {
  std::string text = step.isIndex() ? "[" : first ? "" : ".";
  text += step.isIndex() ? std::to_string(step.index) + "]" : step.key;
  return text;
}

// The index inside "[...]" starting at `open`; returns the position after ']'.
size_t readIndex(const Node& node, const std::string& text, size_t open, size_t& index) {
  const size_t close = text.find(']', open);
  const char* first = text.data() + open + 1;
  const char* last = text.data() + (close == std::string::npos ? text.size() : close);
  auto [end, error] = std::from_chars(first, last, index);
  if (close == std::string::npos || first == last || error != std::errc() || end != last) {
    node.fail("malformed path '" + text + "': expected an index and ']' after column " +
              std::to_string(open + 1));
  }
  return close + 1;
}

// The key starting at `start` (after a '.' or at the beginning); returns the position after it.
size_t readKey(const Node& node, const std::string& text, size_t start, std::string& key) {
  const size_t end = std::min(text.find_first_of(".[]", start), text.size());
  if (end == start) {
    node.fail("malformed path '" + text + "': expected a key at column " + std::to_string(start + 1));
  }
  key = text.substr(start, end - start);
  return end;
}

bool changesGeometry(const std::vector<PathStep>& steps) {
  if (steps[0].key != "objects") return false;
  const bool material = steps.size() >= 3 && steps[1].isIndex() && steps[2].key == "material";
  return !material;
}

// The track's value at one frame of an expression: finite, or an error naming the frame.
double evaluateAt(const Node& node, const std::string& text, int frame, int frames) {
  double value = 0;
  try {
    value = evaluateExpression(text, {double(frame), double(frames)});
  } catch (const ExpressionError& error) {
    node.fail(error.what());
  }
  if (!std::isfinite(value)) {
    // NaN's sign is an accident of the operation that made it (sqrt(-1) gives -nan on x86).
    const std::string shown = std::isnan(value) ? "nan" : formatNumber(value);
    node.fail("evaluates to " + shown + " at frame " + std::to_string(frame) +
              " (i = " + std::to_string(frame) + ", n = " + std::to_string(frames) + ")");
  }
  return value;
}

// One expression element at one frame: a number stays as written, a string is evaluated.
Json elementAt(const Node& node, int frame, int frames) {
  if (node.json().is_number()) return number(node);
  if (node.json().is_string()) return evaluateAt(node, string(node), frame, frames);
  node.fail(std::string("must be a number or a string, got ") + node.json().type_name());
}

Json expressionAt(const Node& node, int frame, int frames) {
  if (node.json().is_string()) return elementAt(node, frame, frames);
  if (!node.json().is_array() || node.json().empty()) {
    node.fail(std::string("must be a string or a non-empty array of numbers and strings, got ") +
              (node.json().is_array() ? "an empty array" : node.json().type_name()));
  }
  Json vector = Json::array();
  for (size_t k = 0; k < node.json().size(); ++k) {
    vector.push_back(elementAt(node.element(k), frame, frames));
  }
  return vector;
}

std::vector<Json> expressionFrames(const Node& node, int frames) {
  std::vector<Json> values;
  for (int i = 0; i < frames; ++i) values.push_back(expressionAt(node, i, frames));
  return values;
}

std::vector<Json> valueFrames(const Node& node, int frames) {
  requireArray(node);
  if (node.json().size() != size_t(frames)) {
    node.fail("length must equal frames (" + std::to_string(frames) + "), got " +
              std::to_string(node.json().size()));
  }
  return std::vector<Json>(node.json().begin(), node.json().end());
}

Track readTrack(const Node& node, int frames) {
  requireObject(node);
  checkKeys(node, kTrackKeys);
  Track track;
  const Node path = node.require("path");
  track.path = string(path);
  track.steps = parseTrackPath(path);
  track.where = node.path();
  track.geometry = changesGeometry(track.steps);
  auto values = node.find("values");
  auto expression = node.find("expression");
  if (values && expression) expression->fail("cannot be given together with 'values'");
  if (!values && !expression) node.fail("needs 'values' or 'expression'");
  track.frames = values ? valueFrames(*values, frames) : expressionFrames(*expression, frames);
  return track;
}

// Where `track` writes in `root`. Every step but the last must exist; the last may add a key.
Json& trackSlot(Json& root, const Track& track, const Node& pathNode) {
  Json* at = &root;
  std::string shown;
  for (size_t k = 0; k < track.steps.size(); ++k) {
    const PathStep& step = track.steps[k];
    const std::string parent = shown;
    shown += stepText(step, k == 0);
    const bool fits = step.isIndex() ? at->is_array() : at->is_object();
    if (!fits) pathNode.fail("'" + shown + "' does not exist ('" + parent + "' is " + at->type_name() + ")");
    const bool last = k + 1 == track.steps.size();
    const bool exists = step.isIndex() ? step.index < at->size() : at->contains(step.key);
    if (!exists && (step.isIndex() || !last)) pathNode.fail("'" + shown + "' does not exist");
    at = step.isIndex() ? &(*at)[step.index] : &(*at)[step.key];
  }
  return *at;
}

}  // namespace

std::vector<PathStep> parseTrackPath(const Node& node) {
  const std::string text = string(node);
  if (text.empty()) node.fail("must not be empty");
  std::vector<PathStep> steps;
  size_t pos = 0;
  while (pos < text.size()) {
    PathStep step;
    if (text[pos] == '[' && !steps.empty()) {
      pos = readIndex(node, text, pos, step.index);
    } else {
      const bool dotted = !steps.empty();
      if (dotted && text[pos] != '.') {
        node.fail("malformed path '" + text + "': unexpected '" + text[pos] + "' at column " +
                  std::to_string(pos + 1));
      }
      pos = readKey(node, text, pos + (dotted ? 1 : 0), step.key);
    }
    steps.push_back(std::move(step));
  }
  if (steps[0].key == "animate") node.fail("cannot animate the animate block");
  return steps;
}

SceneSequence SceneSequence::load(const std::string& path, const ModelView& modelView) {
  if (isModelFile(path)) {
    if (modelView.fileLightShadows && !modelView.fileLights) {
      throw ArgumentError(path + ": shadows from a file's lights need its lights, which are left out");
    }
    SceneSequence model(modelScene(path, modelView), path, "");
    model.modelAlone_ = true;
    return model;
  }
  if (modelView.up) {
    throw ArgumentError(path + ": an up axis applies to a model file rendered alone (.obj .ply .stl .gltf .glb); "
                        "in a scene file each mesh object has its own \"up\"");
  }
  if (!modelView.fileLights) {
    throw ArgumentError(path + ": leaving out a file's lights applies to a model file rendered alone (.gltf .glb); "
                        "in a scene file each mesh object says \"file_lights\"");
  }
  if (modelView.fileLightShadows) {
    throw ArgumentError(path + ": shadows from a file's lights apply to a model file rendered alone (.gltf .glb); "
                        "in a scene file each mesh object says \"file_light_shadows\"");
  }
  if (modelView.orthographic.has_value()) {
    throw ArgumentError(path + ": a projection applies to a model file rendered alone (.obj .ply .stl .gltf .glb); "
                        "a scene file's camera has its own \"projection\"");
  }
  return SceneSequence(parseJson(readSceneText(path), path), path,
                       std::filesystem::path(path).parent_path().string());
}

SceneSequence::SceneSequence(Json json, std::string path, std::string baseDir, bool objectsLater)
    : base_(std::move(json)), path_(std::move(path)), baseDir_(std::move(baseDir)), objectsLater_(objectsLater) {
  if (!base_.is_object() || !base_.contains("animate")) return;  // one frame, checked by frame()
  const Json animate = std::move(base_["animate"]);
  base_.erase("animate");
  const Node node(animate, "animate", path_);
  requireObject(node);
  checkKeys(node, kAnimateKeys);
  frames_ = integer(node.require("frames"), 1, kMaxFrames);
  const Node tracks = node.require("tracks");
  requireArray(tracks);
  for (size_t k = 0; k < tracks.json().size(); ++k) tracks_.push_back(readTrack(tracks.element(k), frames_));
  animated_ = true;
  frameJson(0);  // a path that does not exist fails now, not at the first frame rendered
}

Json SceneSequence::frameJson(int frame) const {
  assert(frame >= 0 && frame < frames_);
  Json json = base_;
  for (const Track& track : tracks_) {
    const Json path = track.path;
    trackSlot(json, track, Node(path, childPath(track.where, "path"), path_)) = track.frames[frame];
  }
  return json;
}

SceneSpec SceneSequence::frame(int frame) const {
  // The frame's JSON tree is read as it is: no text in between.
  const std::string source = animated_ ? path_ + ": frame " + std::to_string(frame) : path_;
  const Json json = frameJson(frame);
  SceneSpec spec = readScene(Node(json, "", source), path_, baseDir_, objectsLater_);
  spec.modelAlone = modelAlone_;
  return spec;
}

bool SceneSequence::geometryDiffers(int a, int b) const {
  for (const Track& track : tracks_) {
    if (track.geometry && track.frames[a] != track.frames[b]) return true;
  }
  return false;
}

}  // namespace phongvk
