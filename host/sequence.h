// sequence.h — `phongvk sequence`: the frames of an animated scene (reference/animate.h) as numbered
// PNGs, and optionally a contact sheet of them.
//
// Frames reuse what they can: one renderer and one upload of the meshes for the whole sequence,
// rebuilt only when a track changes geometry between consecutive frames (or the number of
// materials or lights changes); other frames refresh materials, lights and the view, and the GPU
// renderer then sends only what changed and skips per-vertex lighting when that is legal.
#pragma once

#include "host/app.h"
#include "host/cli_support.h"
#include "reference/animate.h"
#include "reference/camera.h"
#include "reference/render_reference.h"

#include <functional>
#include <string>
#include <vector>

namespace phongvk {

struct SequenceOptions : ViewOptions {
  std::string outputDir;
  std::string frames = ":";  // START:END[:STEP], half-open like a Python slice; ":" is every frame
  std::string sheet;         // contact sheet PNG, optional
  int thumbnailWidth = 160;  // on the sheet; frames are box-filtered down to it, never enlarged
  std::string backend = "gpu";
};

// The frames start, start + step, ... below end.
struct FrameRange {
  int start = 0;
  int end = 0;
  int step = 1;
  int count() const { return 1 + (end - start - 1) / step; }  // precondition: start < end
};

// Reads --frames like a Python slice of the sequence's frames: START:END or START:END:STEP,
// END excluded, START defaulting to 0, END to frameCount, STEP to 1. Unlike Python, indices are
// never negative and never clamped: START < END <= frameCount, or UsageError says why.
FrameRange parseFrameRange(const std::string& text, int frameCount);

// One frame to render: its index in the sequence, its scene and view (validated).
struct SequenceFrame {
  int index = 0;
  Scene scene;
  View view;
};

// The frames of `range`, each at width x height when both are > 0. Every frame is validated
// (scene and view) before any is rendered; throws SceneError naming the frame.
std::vector<SequenceFrame> prepareFrames(const SceneSequence& sequence, const FrameRange& range, int width,
                                         int height);

// A backend as the sequence loop drives it.
class FrameRenderer {
 public:
  virtual ~FrameRenderer() = default;
  // `data` has new geometry (or is the first scene): upload it.
  virtual void load(const SceneData& data) = 0;
  virtual RenderOutput render(const SceneData& data, const FrameInputs& in) = 0;
};

class ReferenceFrameRenderer : public FrameRenderer {
 public:
  void load(const SceneData&) override {}
  RenderOutput render(const SceneData& data, const FrameInputs& in) override;
};

class GpuFrameRenderer : public FrameRenderer {
 public:
  // Creates the context (options.device, options.validate). withKeys also reads back the
  // per-pixel visibility keys (for comparisons).
  GpuFrameRenderer(const ViewOptions& options, bool withKeys);
  void load(const SceneData& data) override;
  RenderOutput render(const SceneData& data, const FrameInputs& in) override;

  const VulkanContext& context() const { return session_.context; }
  // Frames whose per-vertex lighting was recomputed, over every renderer this one has held.
  uint64_t framesShaded() const;
  int uploads() const { return uploads_; }  // how many times geometry was uploaded

 private:
  GpuSession session_;
  bool withKeys_;
  uint64_t shadedByEarlier_ = 0;  // by renderers replaced after a geometry change
  int uploads_ = 0;
};

using FrameSink = std::function<void(const SequenceFrame&, const RenderOutput&)>;

// Renders `frames` (from prepareFrames, in order) with `renderer`, handing each image to `sink`.
// Returns how many times the scene data was built (1 unless geometry changes).
int renderFrames(const SceneSequence& sequence, const std::vector<SequenceFrame>& frames,
                 FrameRenderer& renderer, const FrameSink& sink);

// The file frame `index` is written to: "<dir>/frame_0007.png" (4 digits, more when the
// sequence has more than 10000 frames).
std::string framePath(const std::string& dir, int index, int frameCount);

int runSequence(const SequenceOptions& options);

}  // namespace phongvk
