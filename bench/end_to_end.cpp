// end_to_end.cpp — the CLI's commands run and timed as processes (end_to_end.h).
#include "end_to_end.h"

#include "process.h"

#include "phongvk/phongvk.h"
#include "tools/statistics.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace phongvk::bench {
namespace {

namespace fs = std::filesystem;

struct Setup {
  std::string cli, paper, size;  // size: " --width W --height H" in quick runs
  int rounds = END_TO_END_ROUNDS;
  int frames = 0;                // 0: every frame
  Scratch scratch;
};

SequenceRun measureSequence(const Setup& s, const std::string& name) {
  SequenceRun result;
  result.name = name;
  const std::string scene = quoted(s.paper + "/" + name + ".json");
  const std::string frames = s.frames > 0 ? " --frames 0:" + std::to_string(s.frames) : "";
  std::vector<double> mean, median, fps, seconds, rates;
  for (int round = 0; round < s.rounds; ++round) {
    const fs::path out = s.scratch.dir / "frames";
    fs::remove_all(out);
    const Process sequence = run(s.cli + " sequence " + scene + " -o " + quoted(out.string()) + frames + s.size);
    if (sequence.status != 0) {
      result.failure = "phongvk sequence exited with status " + std::to_string(sequence.status);
      return result;
    }
    result.frames = int(std::distance(fs::directory_iterator(out), {}));
    const int repeat = result.frames > 0 ? result.frames : 1;
    const Process render = run(s.cli + " render " + scene + " -o " + quoted((s.scratch.dir / "still.png").string()) +
                               " --repeat " + std::to_string(repeat) + s.size);
    if (render.status != 0) {
      result.failure = "phongvk render exited with status " + std::to_string(render.status);
      return result;
    }
    fps.push_back(before(sequence.out, " frames/s after the first"));
    seconds.push_back(sequence.seconds);
    median.push_back(after(render.out, "frame ms: median "));
    mean.push_back(after(render.out, ", mean "));
    rates.push_back(fps.back() * mean.back() / 1000.0);
  }
  result.sequenceFps = phongvk::median(fps);
  result.sequenceSeconds = phongvk::median(seconds);
  result.renderMedianMs = phongvk::median(median);
  result.renderMeanMs = phongvk::median(mean);
  result.rateMedian = phongvk::median(rates);
  return result;
}

// One `render` process of `scene` on `backend`, with `environment` assignments before it.
Process renderOnce(const Setup& s, const std::string& scene, const std::string& backend,
                   const std::string& environment = "") {
  return run(environment + s.cli + " render " + quoted(scene) + " -o " + quoted((s.scratch.dir / "still.png").string()) +
             " --backend " + backend + s.size);
}

void readStartup(const Process& gpu, std::vector<double>& vulkan, std::vector<double>& pipelines,
                 std::vector<double>& probe) {
  vulkan.push_back(after(gpu.out, "(start-up: Vulkan "));
  pipelines.push_back(after(gpu.out, ", pipelines "));
  probe.push_back(gpu.out.find("float probe cached") != std::string::npos ? 0.0 : after(gpu.out, ", float probe "));
}

StartupRun measureStartup(const Setup& s, const std::string& name, int rounds, bool fresh) {
  StartupRun result;
  result.name = name;
  const std::string scene = s.paper + "/" + name + ".json";
  std::vector<double> gpuSeconds, cpuSeconds, vulkan, pipelines, probe, withoutPipelines;
  for (int round = 0; round < rounds; ++round) {
    std::string environment;
    if (fresh) {  // a new machine: Mesa's and phongvk's caches (and NVIDIA's) in an empty folder
      const std::string empty = (s.scratch.dir / ("fresh-" + std::to_string(round))).string();
      environment = cachesIn(empty);
      fs::create_directories(empty);
    }
    const Process gpu = renderOnce(s, scene, "gpu", environment);
    const Process cpu = renderOnce(s, scene, "cpu");
    if (gpu.status != 0 || cpu.status != 0) {
      result.failure = "exit status " + std::to_string(gpu.status) + " / " + std::to_string(cpu.status);
      return result;
    }
    gpuSeconds.push_back(gpu.seconds);
    cpuSeconds.push_back(cpu.seconds);
    readStartup(gpu, vulkan, pipelines, probe);
    withoutPipelines.push_back(gpu.seconds - pipelines.back() / 1000.0);
  }
  result.gpuSeconds = phongvk::median(gpuSeconds);
  result.cpuSeconds = phongvk::median(cpuSeconds);
  result.vulkanMs = phongvk::median(vulkan);
  result.pipelinesMs = phongvk::median(pipelines);
  result.probeMs = phongvk::median(probe);
  result.withoutPipelinesSeconds = phongvk::median(withoutPipelines);
  return result;
}

// The first and second render of `scene` (a path under scenes/), each round in a new empty cache.
FirstRun measureFirstRender(const Setup& s, const std::string& scenes, const std::string& scene, int rounds) {
  FirstRun result;
  result.name = scene;
  std::vector<double> first, second, frame;
  for (int round = 0; round < rounds; ++round) {
    const fs::path empty = s.scratch.dir / ("first-" + std::to_string(round));
    fs::remove_all(empty);
    fs::create_directories(empty);
    const std::string environment = cachesIn(empty.string());
    const Process a = renderOnce(s, scenes + "/" + scene, "gpu", environment);
    const Process b = renderOnce(s, scenes + "/" + scene, "gpu", environment);
    if (a.status != 0 || b.status != 0) {
      result.failure = "exit status " + std::to_string(a.status) + " / " + std::to_string(b.status);
      return result;
    }
    first.push_back(a.seconds);
    second.push_back(b.seconds);
    frame.push_back(after(a.out, ", first frame "));
  }
  result.firstSeconds = phongvk::median(first);
  result.secondSeconds = phongvk::median(second);
  result.firstFrameMs = phongvk::median(frame);
  return result;
}

// Every committed scene under `scenes`, as paths relative to it (not the models under meshes/).
std::vector<std::string> committedScenes(const std::string& scenes) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(scenes)) {
    const std::string path = fs::relative(entry.path(), scenes).generic_string();
    if (entry.path().extension() == ".json" && path.find("meshes/") == std::string::npos) names.push_back(path);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> paperScenes(const std::string& paper) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(paper)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

EndToEnd runEndToEnd(const std::string& cli, const std::string& sourceDir, bool quick, const std::string& only) {
  const auto selected = [&](const std::string& name) { return name.find(only) != std::string::npos; };
  Setup s;
  s.cli = quoted(cli);
  s.paper = sourceDir + "/scenes/paper";
  if (quick) {
    s.size = " --width 320 --height 213";
    s.rounds = 1;
    s.frames = 6;
  }
  EndToEnd result;
  const std::vector<std::string> orbits =
      quick ? std::vector<std::string>{"fig7_orbit_white_red"}
            : std::vector<std::string>{"fig6_orbit_red", "fig7_orbit_white_red"};
  for (const std::string& name : orbits) {
    if (!selected(name)) continue;
    result.sequences.push_back(measureSequence(s, name));
    const SequenceRun& r = result.sequences.back();
    std::printf("  sequence %-24s %6.1f frames/s, render --repeat %.2f ms/frame (%.0f%%)\n", name.c_str(),
                r.sequenceFps, r.renderMeanMs, 100 * r.rate());
  }
  const std::vector<std::string> stills = quick ? std::vector<std::string>{"fig1_cube"} : paperScenes(s.paper);
  for (const std::string& name : stills) {
    if (!selected(name)) continue;
    result.startups.push_back(measureStartup(s, name, s.rounds, false));
    const StartupRun& r = result.startups.back();
    std::printf("  start-up %-24s gpu %.3f s, cpu %.3f s (%.2fx)\n", name.c_str(), r.gpuSeconds, r.cpuSeconds,
                r.ratio());
  }
  if (selected("fig1_cube")) {
    result.first = measureStartup(s, "fig1_cube", quick ? 1 : 3, true);
    std::printf("  first render on a new machine: %.2f s\n", result.first.gpuSeconds);
  }
  const std::string scenes = sourceDir + "/scenes";
  const std::vector<std::string> firsts =
      quick ? std::vector<std::string>{"basic.json", "stress/huge_triangles.json"} : committedScenes(scenes);
  for (const std::string& name : firsts) {
    if (!selected(name)) continue;
    result.firsts.push_back(measureFirstRender(s, scenes, name, quick ? 1 : 2));
    const FirstRun& r = result.firsts.back();
    std::printf("  first render %-36s %.2f s, second %.2f s\n", name.c_str(), r.firstSeconds, r.secondSeconds);
  }
  return result;
}

}  // namespace phongvk::bench
