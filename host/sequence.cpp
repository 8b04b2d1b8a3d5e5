#include "sequence.h"

#include "reference/contact_sheet.h"
#include "reference/scene_data.h"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <unistd.h>

namespace phongvk {
namespace {

constexpr int kProgressBarWidth = 30;

// One part of --frames: empty (the default) or a non-negative integer.
int slicePart(const std::string& text, const std::string& part, const char* name, int fallback) {
  if (part.empty()) return fallback;
  int value = -1;
  auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
  if (error != std::errc() || end != part.data() + part.size() || value < 0) {
    throw UsageError("--frames " + text + ": " + name + " '" + part + "' is not a non-negative integer");
  }
  return value;
}

std::vector<std::string> splitColons(const std::string& text) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == ':') parts.emplace_back();
    else parts.back() += c;
  }
  return parts;
}

// Progress on stderr: a bar redrawn in place on a terminal, one line per frame otherwise (logs,
// batch jobs), so a log shows which frame a failure happened at. A frame's time runs from the
// previous report (or the start) and so includes writing its PNG.
class Progress {
 public:
  explicit Progress(int total) : total_(total), terminal_(isatty(fileno(stderr))) {}

  void frameDone(int index, const std::string& file) {
    const double ms = msSince(last_);
    last_ = Clock::now();
    ++done_;
    totalMs_ += ms;
    if (terminal_) {
      drawBar(index);
    } else {
      std::fprintf(stderr, "frame %d (%d/%d): %.1f ms -> %s\n", index, done_, total_, ms, file.c_str());
    }
  }

 private:
  void drawBar(int index) const {
    const int filled = done_ * kProgressBarWidth / total_;
    const double perFrame = totalMs_ / done_;
    std::fprintf(stderr, "\r[%s%s] %d/%d frame %d  %.0f ms/frame  %.0f s left \x1b[K",
                 std::string(filled, '#').c_str(), std::string(kProgressBarWidth - filled, '.').c_str(), done_,
                 total_, index, perFrame, perFrame * (total_ - done_) / 1000);
    if (done_ == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

  int total_;
  bool terminal_;
  int done_ = 0;
  double totalMs_ = 0;
  Clock::time_point last_ = Clock::now();
};

// What becomes of each rendered frame: its PNG, its thumbnail for the sheet, a progress report.
class FrameOutputs {
 public:
  FrameOutputs(const SequenceOptions& options, int frameCount, int selected)
      : options_(options), frameCount_(frameCount), progress_(selected) {}

  void add(const SequenceFrame& frame, const RenderOutput& out) {
    const std::string file = framePath(options_.outputDir, frame.index, frameCount_);
    writePng(file, out.image);
    if (!options_.sheet.empty()) {
      const ThumbnailSize size = thumbnailSize(out.image.width, out.image.height, options_.thumbnailWidth);
      thumbnails_.push_back({frame.index, downscale(out.image, size.width, size.height)});
    }
    progress_.frameDone(frame.index, file);
  }

  void writeSheet() const {
    if (options_.sheet.empty()) return;
    writePng(options_.sheet, contactSheet(thumbnails_, sheetColumns(int(thumbnails_.size()))));
  }

 private:
  const SequenceOptions& options_;
  int frameCount_;
  Progress progress_;
  std::vector<Thumbnail> thumbnails_;
};

// Creates the frames folder and checks every output before the first frame is rendered.
void prepareOutputs(const SequenceOptions& options, int frameCount) {
  checkWritable(options.sheet);  // first, so a bad sheet path leaves no empty frames folder behind
  const std::string& dir = options.outputDir;
  if (std::filesystem::exists(dir) && !std::filesystem::is_directory(dir)) {
    throw OutputError("cannot write frames to '" + dir + "': it exists and is not a folder");
  }
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw OutputError("cannot create folder '" + dir + "': " + error.message());
  checkWritable(framePath(dir, 0, frameCount));
}

std::unique_ptr<FrameRenderer> makeRenderer(const SequenceOptions& options) {
  if (options.backend == "cpu") return std::make_unique<ReferenceFrameRenderer>();
  return std::make_unique<GpuFrameRenderer>(options, false);
}

// "gpu (llvmpipe ...), lighting computed on 1 of 120 frames" or "cpu (reference)".
std::string backendSummary(const FrameRenderer& renderer, int frames) {
  const auto* gpu = dynamic_cast<const GpuFrameRenderer*>(&renderer);
  if (!gpu) return "cpu (reference)";
  return "gpu (" + gpu->context().report.name + "), lighting computed on " + std::to_string(gpu->framesShaded()) +
         " of " + std::to_string(frames) + " frames";
}

void printSummary(const SequenceOptions& options, const FrameRange& range, const View& view,
                  const std::string& backend, int builds, double totalMs) {
  std::printf("sequence %s: frames %d:%d:%d (%d), %dx%d, %s, meshes built %d time%s: %.2f s, %.1f ms/frame"
              " -> %s%s%s\n",
              options.scene.c_str(), range.start, range.end, range.step, range.count(), view.width, view.height,
              backend.c_str(), builds, builds == 1 ? "" : "s", totalMs / 1000, totalMs / range.count(),
              options.outputDir.c_str(), options.sheet.empty() ? "" : ", sheet ", options.sheet.c_str());
}

bool shadingCountsDiffer(const SceneData& data, size_t materials, size_t lights) {
  return data.materials.size() != materials || data.lights.size() != lights;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, int frameCount) {
  const std::vector<std::string> parts = splitColons(text);
  if (parts.size() < 2 || parts.size() > 3) {
    throw UsageError("--frames '" + text +
                     "': expected START:END or START:END:STEP (END excluded, like a Python slice)");
  }
  FrameRange range;
  range.start = slicePart(text, parts[0], "START", 0);
  range.end = slicePart(text, parts[1], "END", frameCount);
  range.step = parts.size() == 3 ? slicePart(text, parts[2], "STEP", 1) : 1;
  const std::string frames = "the sequence has " + std::to_string(frameCount) + " frames";
  if (range.start >= frameCount) {
    throw UsageError("--frames " + text + ": START " + std::to_string(range.start) + " is out of range: " + frames +
                     ", so START < " + std::to_string(frameCount));
  }
  if (range.end > frameCount) {
    throw UsageError("--frames " + text + ": END " + std::to_string(range.end) + " is out of range: " + frames +
                     ", so END <= " + std::to_string(frameCount));
  }
  if (range.start >= range.end) throw UsageError("--frames " + text + ": selects no frames (START must be < END)");
  if (range.step < 1) throw UsageError("--frames " + text + ": STEP must be >= 1");
  return range;
}

std::vector<SequenceFrame> prepareFrames(const SceneSequence& sequence, const FrameRange& range, int width,
                                         int height) {
  std::vector<SequenceFrame> frames;
  for (int64_t i = range.start; i < range.end; i += range.step) {  // 64-bit: a huge STEP may not overflow
    SequenceFrame frame;
    frame.index = int(i);
    frame.scene = sequence.frame(i);
    CameraSpec camera = frame.scene.camera;
    if (width > 0 && height > 0) camera = withImageSize(camera, width, height);
    try {
      frame.view = makeView(camera);
    } catch (const SceneError& error) {
      throw SceneError(sequence.path() + ": frame " + std::to_string(i) + ": " + error.what());
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

RenderOutput ReferenceFrameRenderer::render(const SceneData& data, const FrameInputs& in) {
  return renderReference(data, in);
}

GpuFrameRenderer::GpuFrameRenderer(const ViewOptions& options, bool withKeys)
    : session_(options), withKeys_(withKeys) {}

void GpuFrameRenderer::load(const SceneData& data) {
  shadedByEarlier_ = framesShaded();
  session_.load(data);
  ++uploads_;
}

RenderOutput GpuFrameRenderer::render(const SceneData&, const FrameInputs& in) {
  return session_.renderer->render(in, withKeys_);
}

uint64_t GpuFrameRenderer::framesShaded() const {
  return shadedByEarlier_ + (session_.renderer ? session_.renderer->framesShaded() : 0);
}

int renderFrames(const SceneSequence& sequence, const std::vector<SequenceFrame>& frames, FrameRenderer& renderer,
                 const FrameSink& sink) {
  std::optional<SceneData> data;
  int builds = 0;
  int previous = -1;
  for (const SequenceFrame& frame : frames) {
    bool rebuild = !data || sequence.geometryDiffers(previous, frame.index);
    if (!rebuild) {
      const size_t materials = data->materials.size(), lights = data->lights.size();
      refreshShading(*data, frame.scene);
      // The renderer's buffers are sized for the counts it was built with.
      rebuild = shadingCountsDiffer(*data, materials, lights);
    }
    if (rebuild) {
      data = buildSceneData(frame.scene);
      renderer.load(*data);
      ++builds;
    }
    sink(frame, renderer.render(*data, makeFrame(*data, frame.view)));
    previous = frame.index;
  }
  return builds;
}

std::string framePath(const std::string& dir, int index, int frameCount) {
  const int digits = std::max(4, int(std::to_string(std::max(frameCount - 1, 0)).size()));
  char name[32];
  std::snprintf(name, sizeof name, "frame_%0*d.png", digits, index);
  return (std::filesystem::path(dir) / name).string();
}

int runSequence(const SequenceOptions& options) {
  return guarded([&] {
    const auto start = Clock::now();
    const SceneSequence sequence = SceneSequence::load(options.scene);
    const FrameRange range = parseFrameRange(options.frames, sequence.frameCount());
    const std::vector<SequenceFrame> frames = prepareFrames(sequence, range, options.width, options.height);
    prepareOutputs(options, sequence.frameCount());
    const std::unique_ptr<FrameRenderer> renderer = makeRenderer(options);
    FrameOutputs outputs(options, sequence.frameCount(), range.count());
    const int builds = renderFrames(sequence, frames, *renderer, [&](const SequenceFrame& frame, const RenderOutput& out) {
      outputs.add(frame, out);
    });
    outputs.writeSheet();
    printSummary(options, range, frames[0].view, backendSummary(*renderer, range.count()), builds, msSince(start));
    return int(EXIT_OK);
  });
}

}  // namespace phongvk
