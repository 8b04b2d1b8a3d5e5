// retry_policy.cpp — what a repeated frame grows (retry_policy.h).
#include "compute/retry_policy.h"

#include "phongvk/errors.h"
#include "shaders/gpu_layout.h"

#include <algorithm>

namespace phongvk {

using namespace gpu;

RetryPolicy::RetryPolicy(uint32_t deviceGroupCap, uint32_t firstGroupCap, uint32_t firstListChunk)
    : deviceGroupCap_(deviceGroupCap), firstGroupCap_(firstGroupCap), firstListChunk_(firstListChunk),
      clipFloor_(CLIP_NONE) {
  restart();
}

void RetryPolicy::restart() {
  groupCap_ = firstGroupCap_ != 0 ? std::min(firstGroupCap_, MAX_DISPATCH_GROUPS) : deviceGroupCap_;
  listChunk_ = firstListChunk_;
}

// The clipper first (a triangle to clip met unforeseen), then room for the large triangles, then
// workgroups up to the most a pass launches, then the lists in ever smaller chunks: each is kept
// for the renderer's later frames.
RetryPolicy::Step RetryPolicy::next(uint32_t statusFlags, const std::string& device, bool shadows) {
  Step step;
  if (statusFlags & STATUS_NEEDS_CLIPPING) {
    clipFloor_ = CLIP_ALL;
    step = Step::Clip;
  } else if (statusFlags & STATUS_LARGE_OVERFLOW) {
    step = Step::GrowLists;
  } else if (groupCap_ < MAX_DISPATCH_GROUPS) {
    groupCap_ = std::min(groupCap_ * 16u, MAX_DISPATCH_GROUPS);
    step = Step::MoreGroups;
  } else if (listChunk_ == 0u || listChunk_ > LIST_CHUNK_MIN) {
    listChunk_ = listChunk_ == 0u ? LIST_CHUNK_FIRST : listChunk_ / 4u;
    step = Step::ChunkLists;
  } else {
    throw DeviceError("scene too large for " + device +
                      ": a pass needs more loop iterations per invocation than the device allows, even with " +
                      std::to_string(groupCap_) + " workgroups and the large triangles' lists taken " +
                      std::to_string(listChunk_) + " entries at a time" +
                      (shadows ? "; the shadowed lights' rays are part of that work (fewer shadowed lights fit)" : ""));
  }
  ++framesRepeated_;
  return step;
}

}  // namespace phongvk
