// end_to_end.h — what a user waits for: whole `phongvk` commands, run as processes of the CLI.
// Sequences: `phongvk sequence` on the paper's orbits against `phongvk render --repeat` of the same
// scene (frames per second). Start-up: a one-frame `phongvk render` of each paper scene on the
// compute port against `--backend cpu`, and the first render on a new machine (empty caches).
// First renders: every committed scene's first process on a new machine and its second.
#pragma once

#include <string>
#include <vector>

namespace phongvk::bench {

// `phongvk sequence` at no less than this fraction of `render --repeat`'s frame rate...
inline constexpr double SEQUENCE_RATE_TARGET = 0.8;
// ...and a one-frame render process within this factor of the reference's.
inline constexpr double STARTUP_RATIO_TARGET = 1.5;
// A scene's first render on a new machine within this many seconds, and no more than this many
// above its second render (lavapipe generates each pass's machine code at its first dispatch).
inline constexpr double FIRST_RENDER_TARGET_SECONDS = 1.5;
// Interleaved rounds per measurement (the medians are over these).
inline constexpr int END_TO_END_ROUNDS = 5;

struct SequenceRun {
  std::string name;            // the scene file's name, "fig7_orbit_white_red"
  int frames = 0;
  double renderMeanMs = 0;     // render --repeat: mean wall ms per frame (throughput), median over rounds
  double renderMedianMs = 0;   // and its median frame, as render prints it
  double sequenceFps = 0;      // frames written per second after the first (the sequence's summary)
  double sequenceSeconds = 0;  // the whole process, start-up included
  // Sequence fps / render fps, each round's pair divided, then the median over rounds: the two
  // commands of a round run one after the other, so a slow spell of a shared machine slows both.
  double rateMedian = 0;
  std::string failure;
  double rate() const { return rateMedian; }
};

struct StartupRun {
  std::string name;
  double gpuSeconds = 0;   // one-frame `render` process on the compute port, median over rounds
  double cpuSeconds = 0;   // the same with --backend cpu
  double vulkanMs = 0;     // the compute port's start-up as `render` reports it (median)
  double pipelinesMs = 0;
  double probeMs = 0;      // 0 when cached
  // The compute port's process less its pipeline creation, per round (median): what a driver
  // that kept compiled pipelines across processes would leave. lavapipe keeps none, so there the
  // pipelines stay in every process (docs/DECISIONS.md, "What start-up keeps").
  double withoutPipelinesSeconds = 0;
  std::string failure;
  double ratio() const { return gpuSeconds / cpuSeconds; }
  double floorRatio() const { return withoutPipelinesSeconds / cpuSeconds; }
};

// One committed scene's first `render` process on the compute port with every cache empty, and a
// second in the cache the first left (medians over rounds, each round a new empty cache).
struct FirstRun {
  std::string name;         // the scene's path under scenes/
  double firstSeconds = 0;
  double secondSeconds = 0;
  double firstFrameMs = 0;  // the first process's first frame on the device, as `render` reports it
  std::string failure;
  double excess() const { return firstSeconds - secondSeconds; }
};

struct EndToEnd {
  std::vector<SequenceRun> sequences;
  std::vector<StartupRun> startups;  // warm: the caches hold what earlier runs left
  StartupRun first;                  // the first render on a new machine: empty caches, one run
  std::vector<FirstRun> firsts;      // every committed scene's (quick: two)
};

// Runs the commands with the CLI at `cli`; scenes from `sourceDir`/scenes/paper, only those whose
// name contains `only` (the new-machine render is fig1_cube's; first renders: every scene under
// `sourceDir`/scenes whose path contains it). `quick`: one orbit of a few small frames, one scene's
// start-up and two scenes' first renders, one round.
EndToEnd runEndToEnd(const std::string& cli, const std::string& sourceDir, bool quick, const std::string& only = "");

}  // namespace phongvk::bench
