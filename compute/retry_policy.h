// retry_policy.h — how the compute port renders a frame again when it ran out of room or loop
// iterations (a pass's STATUS_* flags): what to grow next, and what stays grown for later frames.
#pragma once

#include <cstdint>
#include <string>

namespace phongvk {

class RetryPolicy {
 public:
  // deviceGroupCap: the most workgroups a pass launches on the device (gpu_layout.h
  // CPU_DISPATCH_GROUPS, MAX_DISPATCH_GROUPS); firstGroupCap and firstListChunk as
  // GpuRendererOptions (0: the device's cap, whole lists).
  RetryPolicy(uint32_t deviceGroupCap, uint32_t firstGroupCap, uint32_t firstListChunk);

  // A new scene: the workgroup cap and list chunks as a first frame's (the clipper stays).
  void restart();

  // What the next attempt changes, given the last one's status flags.
  enum class Step {
    Clip,        // the clip pass clips from now on (clipFloor)
    GrowLists,   // the caller doubles the large triangles' lists
    MoreGroups,  // 16 times the workgroups per pass (groupCap)
    ChunkLists,  // the bins' lists taken LIST_CHUNK_FIRST entries a round, then a quarter as many each time
  };
  // Counts the repeated frame. Throws DeviceError naming `device` when nothing can grow further,
  // and with `shadows` (a light casts shadows) that their rays are part of the work.
  Step next(uint32_t statusFlags, const std::string& device, bool shadows = false);

  uint32_t groupCap() const { return groupCap_; }
  uint32_t listChunk() const { return listChunk_; }
  uint32_t clipFloor() const { return clipFloor_; }
  uint64_t framesRepeated() const { return framesRepeated_; }

 private:
  uint32_t deviceGroupCap_, firstGroupCap_, firstListChunk_;
  uint32_t groupCap_ = 0;
  uint32_t listChunk_ = 0;
  uint32_t clipFloor_;
  uint64_t framesRepeated_ = 0;
};

}  // namespace phongvk
