// gpu_recording.cpp — one frame's command buffer: reset the lists, then the passes in order
// (shade, triangle and point, clip, bin, resolve large then small, pack), each dispatch capped at the
// workgroup cap and separated by barriers, with timestamps between the stages (PassTimes).
#include "compute/gpu_renderer.h"

#include <algorithm>

namespace phongvk {

using namespace gpu;

namespace {

// The colour buffer's words: the background and pack passes' work items (an invocation each).
uint32_t colorWords(uint32_t width, uint32_t height) { return groupCount(3 * width * height, 4); }

}  // namespace

void GpuRenderer::bindPass(VkCommandBuffer cmd, Pass pass) const {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[pass].pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[pass].layout, 0, 1, &shadeDispatches_[0].set, 0,
                          nullptr);
}

void GpuRenderer::recordFrame(VkCommandBuffer cmd) {
  resetTimestamps(cmd, timestamps_);
  if (keysDirty_) vkCmdFillBuffer(cmd, image_.keys.buffer, 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);  // KEY_CLEAR everywhere
  const VkDeviceSize binBytes = VkDeviceSize(control_.binCount) * sizeof(uint32_t);
  vkCmdFillBuffer(cmd, image_.bins.buffer, sizeof(BinList), binBytes, 0u);                   // no flags
  vkCmdFillBuffer(cmd, image_.bins.buffer, sizeof(BinList) + binBytes, binBytes, LIST_END);  // empty lists
  const BinList noBins = {0, 0, 1, 1};
  vkCmdUpdateBuffer(cmd, image_.bins.buffer, 0, sizeof noBins, &noBins);
  const LargeList emptyList = {0, 0, 0, 0};
  vkCmdUpdateBuffer(cmd, image_.large.buffer.buffer, 0, sizeof emptyList, &emptyList);
  const IdList noClipping = {0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0};
  vkCmdUpdateBuffer(cmd, scene_.clipList.buffer, 0, sizeof noClipping, &noClipping);
  // No triangle kept yet (gpu_layout.h keptWords); a scene that lists its kept triangles instead
  // (keptList) starts its list from the count in IdList and never reads the words.
  if (context_.info.keys32 && !choices_.keptList) {
    vkCmdFillBuffer(cmd, scene_.clipList.buffer, keptWordsOffset(triangleCount_), keptWordsBytes(triangleCount_), 0u);
  }
  transferToComputeBarrier(cmd);

  auto bind = [&](Pass pass) { bindPass(cmd, pass); };
  writeTimestamp(cmd, timestamps_, 0);
  const uint32_t cap = control_.groupCap;
  const uint32_t words = colorWords(frame_.width, frame_.height);
  if (withKeys_) {  // untouched bins are not resolved: their pixels keep this fill
    bind(FILL);
    vkCmdDispatch(cmd, std::min(groupCount(words, FILL_GROUP_SIZE), cap), 1, 1);
  }
  if (control_.shadeColors != 0u || control_.shadePositions != 0u) {  // else last frame's still hold
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[SHADE].pipeline);
    for (const ShadeDispatch& d : shadeDispatches_) {  // one binding's worth of vertices each (ShadeChunk)
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[SHADE].layout, 0, 1, &d.set, 0, nullptr);
      vkCmdPushConstants(cmd, current_[SHADE].layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof d.chunk, &d.chunk);
      vkCmdDispatch(cmd, std::min(groupCount(d.chunk.end - d.chunk.first, SHADE_GROUP_SIZE), cap), 1, 1);
    }
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 1);
  // The triangle and clip passes; on the 32-bit key path twice, the keys' high words and then their
  // low words among the fragments at each pixel's depth (shaders/raster_loops.glsl).
  // The triangle pass's ids dispatch takes a chunk of kept triangles an invocation (gpu_layout.h
  // keptSpan), or in a small scene one listed kept triangle (keptList: indirect, as many as the
  // depth dispatch listed; the clip pass's ids dispatch there walks the clip pass's own kept
  // ones likewise). Before it, the point pass takes a point quad an invocation, the triangle pass
  // the other records (raster_triangles.comp), with no barrier between them: both only offer keys
  // and list records for the clip pass, atomically.
  auto raster = [&](Pass triangles, Pass clip) {
    const uint32_t pointRecords = pointQuads_.y - pointQuads_.x;
    const uint32_t items = triangles == RASTER_IDS ? keptChunks(triangleCount_) : triangleCount_ - pointRecords;
    if (triangles == RASTER_IDS && choices_.keptList) {
      bind(triangles);
      vkCmdDispatchIndirect(cmd, scene_.clipList.buffer, offsetof(IdList, idsGroupsX));
    } else if (items != 0u) {
      bind(triangles);
      vkCmdDispatch(cmd, std::min(groupCount(items, SETUP_GROUP_SIZE), cap), 1, 1);
    }
    if (triangles == RASTER && pointRecords != 0u) {
      bind(RASTER_POINTS);
      vkCmdDispatch(cmd, std::min(groupCount(pointRecords / 2u, SETUP_GROUP_SIZE), cap), 1, 1);
    }
    computeBarrier(cmd);
    bind(clip);
    const bool keptClipped = clip == CLIP_IDS && choices_.keptList;  // the clip pass's kept ones only
    vkCmdDispatchIndirect(cmd, scene_.clipList.buffer,
                          keptClipped ? offsetof(IdList, clipIdsGroupsX) : offsetof(IdList, groupsX));
    computeBarrier(cmd);
  };
  raster(RASTER, CLIP);
  if (context_.info.keys32) raster(RASTER_IDS, CLIP_IDS);
  if (choices_.binPass) {
    bind(BIN_LARGE);
    vkCmdDispatchIndirect(cmd, scene_.clipList.buffer, offsetof(IdList, binGroupsX));
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 2);
  recordResolveLargeRound(cmd);
  if (choices_.listChunk == 0u) recordResolveTail(cmd);  // else after the rounds (renderAttempt)
}

// Resolve over the touched bins (indirect): the large triangles, all of them or (choices_.listChunk) the
// next chunk of each bin's list.
void GpuRenderer::recordResolveLargeRound(VkCommandBuffer cmd) {
  bindPass(cmd, RESOLVE_LARGE);
  vkCmdDispatchIndirect(cmd, image_.bins.buffer, offsetof(BinList, groupsX));
  computeBarrier(cmd);
}

// The rest of the frame after resolve_large: small reads the keys large left, then the pack pass
// and, for diffs, the keys' copy. The barrier after each dispatch also keeps lavapipe from writing
// the next timestamp before the dispatch ends.
void GpuRenderer::recordResolveTail(VkCommandBuffer cmd) {
  bindPass(cmd, RESOLVE_SMALL);
  vkCmdDispatchIndirect(cmd, image_.bins.buffer, offsetof(BinList, groupsX));
  computeBarrier(cmd);
  if (packsColors(choices_, withKeys_)) {  // the colours from the key slots into the colour buffer
    bindPass(cmd, PACK);
    vkCmdDispatch(cmd, std::min(groupCount(colorWords(frame_.width, frame_.height), PACK_GROUP_SIZE), control_.groupCap),
                  1, 1);
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 3);
  if (withKeys_) {  // resolve left the final keys: copy them; the next frame clears them
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferCopy keyCopy = {0, 0, VkDeviceSize(frame_.width) * frame_.height * sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, image_.keys.buffer, image_.keyReadback.buffer, 1, &keyCopy);
  }
}

}  // namespace phongvk
