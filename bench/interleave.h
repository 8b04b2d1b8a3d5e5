// interleave.h — timing two or more ways of rendering against each other through the public
// Renderer, in interleaved rounds, so a burst of load slows every side alike.
#pragma once

#include "api/timing.h"
#include "phongvk/phongvk.h"

#include <functional>
#include <vector>

namespace phongvk::bench {

// One side of the comparison: its renderer, the scene of its frame k (made or changed before the
// clock starts: the user's side of the frame; it stays the side's until its next frame), and
// where its frame times go.
struct InterleavedSide {
  Renderer& renderer;
  std::function<const Scene&(int k)> frame;
  std::vector<double>& ms;
};

// `rounds` rounds, each `frames` frames of every side in turn, timed one by one; frame k of each
// side is the same k (from `first` on), so the sides render the same frames.
inline void timeInterleaved(const std::vector<InterleavedSide>& sides, int rounds, int frames, int first = 1) {
  int k = first;
  for (int round = 0; round < rounds; ++round) {
    for (const InterleavedSide& side : sides) {
      for (int f = 0; f < frames; ++f) {
        const Scene& scene = side.frame(k + f);
        const auto start = Clock::now();
        side.renderer.render(scene);
        side.ms.push_back(msSince(start));
      }
    }
    k += frames;
  }
}

}  // namespace phongvk::bench
