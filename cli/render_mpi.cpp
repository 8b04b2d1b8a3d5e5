// render_mpi.cpp — `mpirun -np N phongvk render SCENE -o OUT --mpi`: one scene across N processes,
// composited sort-last by the 64-bit visibility keys (docs/DESIGN.md "One scene across
// processes"). Each rank renders its share of the triangles (Scene::share) with keys naming the
// whole scene's triangles; MPI_Allreduce with MPI_MIN makes every rank's keys the whole scene's
// (the smallest key wins a pixel, as in one process); each rank then keeps the pixels whose winner
// is its own, and an MPI_Reduce with MPI_BOR over the RGB bytes (every other rank gives 0 there)
// puts the image together on rank 0, which writes the PNG. Bytes equal to one process's render.
#include "cli/cli_support.h"

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

struct Composited {
  Image image;
  double keysMs = 0, colorsMs = 0;
  uint64_t keyBytes = 0, colorBytes = 0;
};

// The whole scene's image from this rank's share: the keys' minimum over all ranks, then each
// pixel's colour from the rank whose triangle won it (rank 0 also gives the background).
Composited composite(const RenderOutput& share, int rank) {
  Composited c;
  std::vector<uint64_t> keys(share.keys.size());
  c.keyBytes = keys.size() * sizeof(uint64_t);
  MPI_Barrier(MPI_COMM_WORLD);  // the times below are the reductions', not the slowest rank's render
  const auto keysStart = Clock::now();
  MPI_Allreduce(share.keys.data(), keys.data(), int(keys.size()), MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  c.keysMs = msSince(keysStart);
  std::vector<uint8_t> mine(share.image.rgb.size(), 0);
  for (size_t i = 0; i < keys.size(); ++i) {
    const bool won = keys[i] != ~uint64_t(0) && keys[i] == share.keys[i];
    const bool background = keys[i] == ~uint64_t(0) && rank == 0;
    if (!won && !background) continue;
    for (int k = 0; k < 3; ++k) mine[3 * i + k] = share.image.rgb[3 * i + k];
  }
  c.image = Image(share.image.width, share.image.height);
  c.colorBytes = mine.size();
  const auto colorsStart = Clock::now();
  MPI_Reduce(mine.data(), c.image.rgb.data(), int(mine.size()), MPI_UINT8_T, MPI_BOR, 0, MPI_COMM_WORLD);
  c.colorsMs = msSince(colorsStart);
  return c;
}

// Every rank reaches the same verdict on a failure: a rank that fails says why and aborts the job,
// so no rank waits in a collective for one that left.
int renderShare(const RenderOptions& options, const MpiSession& mpi) {
  const int rank = mpi.rank(), ranks = mpi.size();
  if (options.repeat > 0) throw UsageError("--repeat times one process's frames: it does not go with --mpi");
  if (rank == 0) checkWritable(options.output);
  const Scene scene = loadEveryFrameValidated(options);
  const auto start = Clock::now();
  Renderer renderer(rendererOptions(options, options.backend));
  const RenderOutput share = renderer.renderWithKeys(scene.share(rank, ranks));
  if (share.keys.size() != size_t(share.image.width) * share.image.height) {
    throw UsageError("--mpi composites one sample per pixel: render.samples (or --samples) must be 1");
  }
  const double renderMs = msSince(start);
  const Composited c = composite(share, rank);
  if (rank != 0) return EXIT_OK;
  writePng(options.output, c.image, options.pngLevel);
  std::printf("rendered %s with %d processes: %dx%d, %zu triangles on rank 0, %s backend: render %.1f ms (rank 0), "
              "composite keys %.1f ms (MPI_Allreduce MPI_MIN, %llu bytes per rank), colours %.1f ms (MPI_Reduce "
              "MPI_BOR, %llu bytes per rank) -> %s\n",
              options.scene.c_str(), ranks, c.image.width, c.image.height, renderer.stats().triangles,
              backendName(renderer.backend()), renderMs, c.keysMs, static_cast<unsigned long long>(c.keyBytes),
              c.colorsMs, static_cast<unsigned long long>(c.colorBytes), options.output.c_str());
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
