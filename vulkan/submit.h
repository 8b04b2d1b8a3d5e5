// commands.h — one-time command buffers, barriers between compute passes, GPU timestamps.
//
//   VkCommandBuffer cmd = beginOneTimeCommands(context);
//   vkCmdDispatch(cmd, ...);
//   computeBarrier(cmd);
//   vkCmdDispatch(cmd, ...);
//   submitAndWait(context, cmd);   // results are now readable through mapped memory
#pragma once

#include "vulkan/context.h"
#include "vulkan/owned.h"

#include <chrono>
#include <vector>

namespace phongvk {

// How long submitAndWait waits before it calls the GPU hung. Generous: a large frame on lavapipe
// with two CPU cores takes seconds, a hang (an endless shader loop) takes forever.
inline constexpr std::chrono::seconds kGpuTimeout{120};

// A primary command buffer from context.commandPool, begun for one submission.
VkCommandBuffer beginOneTimeCommands(const VulkanContext& context);

// Ends `cmd`, submits it, waits for it and frees it. It first records a full memory barrier, so
// everything the submission wrote is visible to the host (mapped buffers) and to later submissions.
// Throws VulkanError (result VK_TIMEOUT) if the GPU does not finish within `timeout`.
void submitAndWait(const VulkanContext& context, VkCommandBuffer cmd, std::chrono::nanoseconds timeout = kGpuTimeout);

// A global memory barrier from (srcStage, srcAccess) to (dstStage, dstAccess).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// Between dependent compute passes: shader writes of the earlier dispatches become visible to
// shader reads/writes (and atomics) of later dispatches and to indirect dispatch arguments.
void computeBarrier(VkCommandBuffer cmd);

// After vkCmdFillBuffer / vkCmdCopyBuffer / vkCmdUpdateBuffer, before shaders use the data.
void transferToComputeBarrier(VkCommandBuffer cmd);

// Timestamps written by the GPU between passes. All calls are no-ops when !context.timestamps.
struct TimestampPoolHandles {
  VkQueryPool pool = VK_NULL_HANDLE;
  uint32_t count = 0;
  double periodNs = 0;          // nanoseconds per tick (limits.timestampPeriod)
  uint64_t validMask = 0;       // timestamps wrap modulo 2^timestampValidBits
};
void destroyTimestampPool(TimestampPoolHandles& pool, const VulkanContext& context);
// The query pool, freed when it goes (owned.h).
using TimestampPool = Owned<TimestampPoolHandles, destroyTimestampPool>;

void createTimestampPool(TimestampPool& result, const VulkanContext& context, uint32_t count);

// Record once per submission, before the first writeTimestamp: a query must be reset before reuse.
void resetTimestamps(VkCommandBuffer cmd, const TimestampPool& pool);

// Records the time at which all earlier commands in the submission have completed.
void writeTimestamp(VkCommandBuffer cmd, const TimestampPool& pool, uint32_t slot);

// After the submission finished: milliseconds from slot 0 to each slot (so element 0 is 0), NaN
// for a slot not written. Empty when timestamps are unsupported.
std::vector<double> readTimestamps(const VulkanContext& context, const TimestampPool& pool);

}  // namespace phongvk
