// render_mpi.cpp — `mpirun -np N phongvk render SCENE -o OUT --mpi`: one scene across N processes,
// composited sort-last by the 64-bit visibility keys (docs/DESIGN.md "One scene across
// processes"). Each rank renders its share of the triangles (Scene::share) once, with the outputs
// asked for (--rgba, --depth, --ids, --normals) and keys naming the whole scene's triangles;
// MPI_Allreduce with MPI_MIN makes every rank's keys the whole scene's (the smallest key wins a
// pixel, as in one process); each rank then zeroes the pixels whose winner is not its own, and
// MPI_Reduce with MPI_BOR over the colours' bytes and the outputs' bit patterns (every other rank
// gives 0 bits there) puts the frame together on rank 0, which writes the files as one process
// does (render_outputs.h). Bytes equal to one process's render.
#include "cli/cli_support.h"
#include "cli/render_outputs.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <string>
#include <vector>

#ifdef PHONGVK_WITH_MPI
#include <mpi.h>
#endif

namespace phongvk::cli {

#ifndef PHONGVK_WITH_MPI

int runRenderMpi(const RenderOptions&) {
  return guarded([]() -> int {
    throw UsageError("--mpi: this phongvk was built without MPI (install libopenmpi-dev and rebuild; "
                     "PHONGVK_MPI=ON, the default, then finds it)");
  });
}

#else

namespace {

// MPI_Init and MPI_Finalize around the command, also when it throws.
struct MpiSession {
  MpiSession() { MPI_Init(nullptr, nullptr); }
  ~MpiSession() { MPI_Finalize(); }
  int rank() const {
    int r = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
  }
  int size() const {
    int n = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &n);
    return n;
  }
};

// The frame's visibility keys, one per pixel, (depth bits << 32) | triangle and all ones where
// empty (image.h RenderOutput): put back together from the depth and triangle ids the renderer read
// out of them (visibilityOf), so one render gives both the keys and the outputs.
std::vector<uint64_t> keysOf(const RenderedFrame& frame) {
  std::vector<uint64_t> keys(frame.triangleIds.size(), ~uint64_t(0));
  for (size_t i = 0; i < keys.size(); ++i) {
    if (frame.triangleIds[i] == -1) continue;  // NO_TRIANGLE
    keys[i] = uint64_t(std::bit_cast<uint32_t>(frame.depth[i])) << 32 | std::bit_cast<uint32_t>(frame.triangleIds[i]);
  }
  return keys;
}

// Zeroes the pixels (`perPixel` values each) this rank does not keep; an output not asked for is
// empty and stays so.
template <class T>
void keepOnly(std::vector<T>& values, size_t perPixel, const std::vector<uint8_t>& keep) {
  if (values.empty()) return;
  for (size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) std::fill_n(values.begin() + i * perPixel, perPixel, T(0));
  }
}

// MPI_BOR of every rank's `values` onto rank 0's, in place, over their bit patterns (bytes, or
// 32-bit words for floats and int32): a value only one rank gives passes through bit for bit. An
// output not asked for is empty on every rank and is not reduced.
template <class T>
void reduceBits(std::vector<T>& values, int rank) {
  if (values.empty()) return;
  static_assert(sizeof(T) == 1 || sizeof(T) == 4);
  const MPI_Datatype type = sizeof(T) == 1 ? MPI_UINT8_T : MPI_UINT32_T;
  MPI_Reduce(rank == 0 ? MPI_IN_PLACE : values.data(), values.data(), int(values.size()), type, MPI_BOR, 0,
             MPI_COMM_WORLD);
}

struct Composited {
  double keysMs = 0, pixelsMs = 0;
  uint64_t keyBytes = 0, pixelBytes = 0;
  std::string what;  // what the pixels' reduction carried: "RGB, depth, object ids, normals"
};

// The whole scene's frame on rank 0 from each rank's share, in place: the keys' minimum over all
// ranks, then each pixel's colour and outputs from the rank whose triangle won it (rank 0 also
// gives the empty pixels': the background, depth +inf, id -1, normal 0), and the alpha from the
// whole scene's keys (one sample: 255 where a triangle won, else 0). Other ranks' frames end up
// holding their own pixels only.
Composited composite(RenderedFrame& frame, const RenderOptions& options, int rank) {
  Composited c;
  const uint64_t EMPTY = ~uint64_t(0);
  std::vector<uint64_t> mine = keysOf(frame);
  std::vector<uint64_t> keys(mine.size());
  c.keyBytes = keys.size() * sizeof(uint64_t);
  MPI_Barrier(MPI_COMM_WORLD);  // the times below are the reductions', not the slowest rank's render
  const auto keysStart = Clock::now();
  MPI_Allreduce(mine.data(), keys.data(), int(keys.size()), MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  c.keysMs = msSince(keysStart);
  std::vector<uint8_t> keep(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) keep[i] = keys[i] == EMPTY ? rank == 0 : keys[i] == mine[i];
  if (rank == 0 && options.rgba) {
    frame.alpha.resize(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) frame.alpha[i] = keys[i] == EMPTY ? 0 : 255;
  }
  mine = {};
  keys = {};
  frame.triangleIds = {};
  if (options.depth.empty()) frame.depth = {};
  // Each pixel's values, zero on every rank but the one that keeps them, combined by MPI_BOR.
  keepOnly(frame.image.rgb, 3, keep);
  keepOnly(frame.depth, 1, keep);
  keepOnly(frame.objectIds, 1, keep);
  keepOnly(frame.normals, 3, keep);
  keepOnly(frame.lights, 1, keep);
  c.what = "RGB";
  if (!frame.depth.empty()) c.what += ", depth";
  if (!frame.objectIds.empty()) c.what += ", object ids";
  if (!frame.normals.empty()) c.what += ", normals";
  if (!frame.lights.empty()) c.what += ", lights";
  c.pixelBytes = frame.image.rgb.size() +
                 4 * (frame.depth.size() + frame.objectIds.size() + frame.normals.size() + frame.lights.size());
  const auto pixelsStart = Clock::now();
  reduceBits(frame.image.rgb, rank);
  reduceBits(frame.depth, rank);
  reduceBits(frame.objectIds, rank);
  reduceBits(frame.normals, rank);
  reduceBits(frame.lights, rank);
  c.pixelsMs = msSince(pixelsStart);
  return c;
}

// Every rank reaches the same verdict on a failure: a rank that fails says why and aborts the job,
// so no rank waits in a collective for one that left. Every check comes before rendering, and
// every file is written by rank 0 after compositing.
int renderShare(const RenderOptions& options, const MpiSession& mpi) {
  const int rank = mpi.rank(), ranks = mpi.size();
  if (options.repeat > 0) throw UsageError("--repeat times one process's frames: it does not go with --mpi");
  if (parseBackend(options.backend) == Backend::Graphics) {
    throw UsageError("--mpi composites by the visibility keys, which the graphics backend does not have: use the "
                     "gpu or cpu backend");
  }
  Outputs outputs = outputsAsked(options);
  if (rank == 0) checkWritable(options.output);
  const Scene scene = loadEveryFrameValidated(options);
  if (scene.renderSettings().samples != 1) {
    throw UsageError("--mpi composites one sample per pixel: render.samples (or --samples) must be 1");
  }
  if (rank == 0) checkOutputFiles(options, scene);
  const auto start = Clock::now();
  Renderer renderer(rendererOptions(options, options.backend));
  // The keys come from the depth and the triangle ids; the alpha comes from the composited keys.
  outputs.alpha = false;
  outputs.depth = outputs.triangleIds = true;
  RenderedFrame frame = renderer.renderOutputs(scene.share(rank, ranks), outputs);
  const double renderMs = msSince(start);
  const Composited c = composite(frame, options, rank);
  if (rank != 0) return EXIT_OK;
  writeRenderedFiles(options, frame);
  std::printf("rendered %s with %d processes: %dx%d, %zu triangles on rank 0, %s backend: render %.1f ms (rank 0), "
              "composite keys %.1f ms (MPI_Allreduce MPI_MIN, %llu bytes per rank), colours %.1f ms (MPI_Reduce "
              "MPI_BOR, %llu bytes per rank: %s%s) -> %s\n",
              options.scene.c_str(), ranks, frame.image.width, frame.image.height, renderer.stats().triangles,
              backendName(renderer.backend()), renderMs, c.keysMs, static_cast<unsigned long long>(c.keyBytes),
              c.pixelsMs, static_cast<unsigned long long>(c.pixelBytes), c.what.c_str(),
              options.rgba ? "; alpha from the keys" : "", options.output.c_str());
  return EXIT_OK;
}

}  // namespace

int runRenderMpi(const RenderOptions& options) {
  MpiSession mpi;
  const int code = guarded([&] { return renderShare(options, mpi); });
  if (code != EXIT_OK) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}

#endif

}  // namespace phongvk::cli
