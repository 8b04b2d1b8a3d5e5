// sequence.cpp — `phongvk sequence`: the frames of an animated scene (docs/DESIGN.md, "animate") as
// numbered PNGs, and optionally a contact sheet of them. One Renderer renders every frame, so the
// meshes are built and uploaded once unless a track changes geometry (Renderer keeps them), and
// the GPU backend sends only what changed and skips per-vertex lighting where that is legal.
#include "cli/sequence.h"

#include "cli/cli_support.h"
#include "tools/contact_sheet.h"
#include "tools/frame_writer.h"
#include "tools/png_check.h"
#include "tools/output_memory.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <mutex>
#include <vector>

namespace phongvk::cli {
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
// previous report (or the start): with frames written beside rendering, the pace frames reach disk.
class Progress {
 public:
  explicit Progress(int total) : total_(total), terminal_(isatty(fileno(stderr))) {}

  void frameDone(int index, const std::string& file) {
    const double ms = msSince(last_);
    last_ = Clock::now();
    if (done_ == 0) firstDone_ = last_;
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
  Clock::time_point firstDone_;

 public:
  // Frames written per second after the first (whose time holds the pipelines' compilation):
  // the pace of a long sequence. NaN for fewer than two frames.
  double steadyFramesPerSecond() const {
    if (done_ < 2) return std::numeric_limits<double>::quiet_NaN();
    return (done_ - 1) / std::chrono::duration<double>(last_ - firstDone_).count();
  }
};

// What becomes of each rendered frame: its PNG, written by the FrameWriter's threads while the
// next frames render, its thumbnail for the sheet, a progress report.
class FrameOutputs {
 public:
  FrameOutputs(const SequenceOptions& options, int frameCount, int selected)
      : options_(options),
        frameCount_(frameCount),
        progress_(selected),
        writer_(FrameWriter::defaultThreads(), 2 * FrameWriter::defaultThreads(), options.pngLevel,
                [this](const FrameFile& frame) { written(frame); }) {}

  Image spareImage() { return writer_.spareImage(); }

  void add(int index, Image image) {
    writer_.push({index, framePath(options_.outputDir, index, frameCount_), std::move(image)});
  }

  // Frame `index`, kept from an earlier run (--skip-existing): its thumbnail from the file.
  void kept(int index, const std::string& path) {
    if (!options_.sheet.empty()) thumbnail(index, readPng(path));
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_.frameDone(index, path + " (kept)");
  }

  const Progress& progress() const { return progress_; }

  // Waits for every frame's file, then writes the sheet (not for an interrupted sequence: it would
  // lack frames).
  void finish(bool interrupted = false) {
    writer_.finish();
    if (options_.sheet.empty() || interrupted) return;
    std::sort(thumbnails_.begin(), thumbnails_.end(),
              [](const Thumbnail& a, const Thumbnail& b) { return a.frame < b.frame; });
    writePng(options_.sheet, contactSheet(thumbnails_, sheetColumns(int(thumbnails_.size()))), options_.pngLevel);
  }

 private:
  // On a writer thread, one frame at a time (the main thread reports kept frames meanwhile).
  void written(const FrameFile& frame) {
    if (!options_.sheet.empty()) thumbnail(frame.index, frame.image);
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_.frameDone(frame.index, frame.path);
  }

  void thumbnail(int index, const Image& image) {
    const ThumbnailSize size = thumbnailSize(image.width, image.height, options_.thumbnailWidth);
    Thumbnail t{index, downscale(image, size.width, size.height)};
    const std::lock_guard<std::mutex> lock(mutex_);
    thumbnails_.push_back(std::move(t));
  }

  const SequenceOptions& options_;
  int frameCount_;
  std::mutex mutex_;  // progress_ and thumbnails_: the writer threads and the main thread
  Progress progress_;
  std::vector<Thumbnail> thumbnails_;
  FrameWriter writer_;  // last: its threads stop before the members they report to go
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

void printSummary(const SequenceOptions& options, const FrameRange& range, const Scene& first,
                  const std::string& backend, uint64_t builds, double totalMs, double steadyFps) {
  std::printf("sequence %s: frames %d:%d:%d (%d), %dx%d, %s, meshes built %d time%s: %.2f s, %.1f ms/frame, "
              "%.1f frames/s after the first -> %s%s%s\n",
              options.scene.c_str(), range.start, range.end, range.step, range.count(), first.width(), first.height(),
              backend.c_str(), int(builds), builds == 1 ? "" : "s", totalMs / 1000, totalMs / range.count(), steadyFps,
              options.outputDir.c_str(), options.sheet.empty() ? "" : ", sheet ", options.sheet.c_str());
}

// Every frame's scene, at the asked size, validated before any is rendered: a bad frame 17 fails
// before frame 0 is written.
std::vector<Scene> prepareFrames(const Scene& sequence, const FrameRange& range, const ViewOptions& options) {
  std::vector<Scene> frames;
  for (int64_t i = range.start; i < range.end; i += range.step) {  // 64-bit: a huge STEP may not overflow
    frames.push_back(frameAsAsked(sequence, int(i), options));
  }
  return frames;
}

// The contact sheet's thumbnails, held until the last frame, and the sheet: checked against the
// memory limit with the frames, before any is rendered (100,000 frames at --thumb-width 4096 would
// ask for terabytes at the end of the run).
void checkSheetMemory(const SequenceOptions& options, const Scene& sequence, const std::vector<Scene>& frames) {
  if (options.sheet.empty()) return;
  ThumbnailSize cell = {1, 1};
  for (const Scene& frame : frames) {
    const ThumbnailSize size = thumbnailSize(frame.width(), frame.height(), options.thumbnailWidth);
    cell = {std::max(cell.width, size.width), std::max(cell.height, size.height)};
  }
  checkOutputMemory(sequence.path(), "the contact sheet", contactSheetBytes(int(frames.size()), cell),
                    std::to_string(frames.size()) + " thumbnails of " + std::to_string(cell.width) + "x" +
                        std::to_string(cell.height),
                    "a smaller --thumb-width or fewer --frames fit");
}

// "gpu (llvmpipe ...), lighting computed on 1 of 120 frames" or "cpu (reference)".
std::string backendSummary(const Renderer& renderer, int frames) {
  if (renderer.backend() == Backend::Cpu) return "cpu (reference)";
  return "gpu (" + renderer.deviceName() + "), lighting computed on " + std::to_string(renderer.stats().framesShaded) +
         " of " + std::to_string(frames) + " frames";
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

std::string framePath(const std::string& dir, int index, int frameCount) {
  const int digits = std::max(4, int(std::to_string(std::max(frameCount - 1, 0)).size()));
  char name[32];
  std::snprintf(name, sizeof name, "frame_%0*d.png", digits, index);
  return (std::filesystem::path(dir) / name).string();
}

// SIGINT or SIGTERM while the frames render: the sequence stops after the frame in flight.
std::atomic<int> interruptedBy{0};

extern "C" void onInterrupt(int signal) { interruptedBy = signal; }

// Catches SIGINT and SIGTERM for its lifetime (the default dispositions come back after).
class InterruptGuard {
 public:
  InterruptGuard() {
    interruptedBy = 0;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &oldInt_);
    sigaction(SIGTERM, &action, &oldTerm_);
  }
  ~InterruptGuard() {
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
  }

 private:
  struct sigaction oldInt_ {}, oldTerm_ {};
};

int runSequence(const SequenceOptions& options) {
  const InterruptGuard interrupts;
  return guarded([&] {
    const auto start = Clock::now();
    const Scene sequence = loadScene(options.scene, loadOptions(options));
    const FrameRange range = parseFrameRange(options.frames, sequence.frameCount());
    const std::vector<Scene> frames = prepareFrames(sequence, range, options);
    const RendererOptions rendering = rendererOptions(options, options.backend);
    checkSheetMemory(options, sequence, frames);
    prepareOutputs(options, sequence.frameCount());
    Renderer renderer(rendering);
    FrameOutputs outputs(options, sequence.frameCount(), range.count());
    size_t rendered = 0, kept = 0;
    for (; rendered < frames.size() && interruptedBy == 0; ++rendered) {
      const int index = int(range.start + int64_t(rendered) * range.step);
      const std::string path = framePath(options.outputDir, index, sequence.frameCount());
      if (options.skipExisting && pngIsComplete(path, frames[rendered].width(), frames[rendered].height())) {
        outputs.kept(index, path);
        ++kept;
        continue;
      }
      Image image = outputs.spareImage();
      renderer.render(frames[rendered], image);
      outputs.add(index, std::move(image));
    }
    outputs.finish(interruptedBy != 0);  // every frame rendered is written whole
    if (const int signal = interruptedBy) {
      std::fprintf(stderr,
                   "sequence %s: interrupted (%s) after %zu of %d frames, each written whole to %s; run the same "
                   "command again to complete the set\n",
                   options.scene.c_str(), signal == SIGINT ? "SIGINT" : "SIGTERM", rendered, range.count(),
                   options.outputDir.c_str());
      return 128 + signal;
    }
    printSummary(options, range, frames[0], backendSummary(renderer, range.count()), renderer.stats().sceneBuilds,
                 msSince(start), outputs.progress().steadyFramesPerSecond());
    if (kept > 0) std::printf("kept %zu frame%s an earlier run wrote whole\n", kept, kept == 1 ? "" : "s");
    return int(EXIT_OK);
  });
}

}  // namespace phongvk::cli
