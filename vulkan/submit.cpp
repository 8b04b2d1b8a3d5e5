// submit.cpp — one-time submissions, barriers, timestamp queries.
#include "vulkan/submit.h"

#include "vulkan/vk_check.h"

#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

namespace phongvk {

VkCommandBuffer beginOneTimeCommands(const VulkanContext& context) {
  VkCommandBufferAllocateInfo allocateInfo = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO };
  allocateInfo.commandPool = context.commandPool;
  allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocateInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(context.device, &allocateInfo, &cmd));

  VkCommandBufferBeginInfo beginInfo = { VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO };
  beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VkResult result = vkBeginCommandBuffer(cmd, &beginInfo);
  if (result != VK_SUCCESS) vkFreeCommandBuffers(context.device, context.commandPool, 1, &cmd);
  VK_CHECK(result);
  return cmd;
}

namespace {

// Submits and waits on the context's fence (left pending on a timeout: the device is unusable
// then, and destroyContext waits for it). Returns the wait's result.
VkResult submitWithFence(const VulkanContext& context, VkCommandBuffer cmd, std::chrono::nanoseconds timeout) {
  VK_CHECK(vkResetFences(context.device, 1, &context.fence));
  VkSubmitInfo submit = { VK_STRUCTURE_TYPE_SUBMIT_INFO };
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VkResult result = vkQueueSubmit(context.queue, 1, &submit, context.fence);
  if (result == VK_SUCCESS) result = vkWaitForFences(context.device, 1, &context.fence, VK_TRUE, timeout.count());
  return result;
}

}  // namespace

void submitAndWait(const VulkanContext& context, VkCommandBuffer cmd, std::chrono::nanoseconds timeout) {
  // Makes the submission's writes available and visible to the host and to later submissions,
  // so callers never need a barrier at the end of a command buffer.
  memoryBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_HOST_READ_BIT);
  VK_CHECK(vkEndCommandBuffer(cmd));

  VkResult result = submitWithFence(context, cmd, timeout);
  if (result == VK_TIMEOUT) {
    // The command buffer is still pending and cannot be freed; the device is unusable anyway.
    throw VulkanError("the GPU did not finish within " +
                          std::to_string(std::chrono::duration_cast<std::chrono::seconds>(timeout).count()) +
                          " s (a hang or an endless shader loop): VK_TIMEOUT",
                      VK_TIMEOUT);
  }
  vkFreeCommandBuffers(context.device, context.commandPool, 1, &cmd);
  VK_CHECK(result);
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkMemoryBarrier barrier = { VK_STRUCTURE_TYPE_MEMORY_BARRIER };
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void computeBarrier(VkCommandBuffer cmd) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
}

void transferToComputeBarrier(VkCommandBuffer cmd) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT);
}

void createTimestampPool(TimestampPool& result, const VulkanContext& context, uint32_t count) {
  assert(count > 0);
  result = TimestampPool({}, context);
  if (!context.timestamps) return;
  VkQueryPoolCreateInfo info = { VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO };
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = count;
  VK_CHECK(vkCreateQueryPool(context.device, &info, nullptr, &result.pool));
  result.count = count;
  result.periodNs = context.properties.limits.timestampPeriod;
  result.validMask = context.timestampValidBits >= 64 ? ~0ull : (1ull << context.timestampValidBits) - 1;
}

void destroyTimestampPool(TimestampPoolHandles& pool, const VulkanContext& context) {
  if (pool.pool) vkDestroyQueryPool(context.device, pool.pool, nullptr);
  pool = {};
}

void resetTimestamps(VkCommandBuffer cmd, const TimestampPool& pool) {
  if (pool.pool) vkCmdResetQueryPool(cmd, pool.pool, 0, pool.count);
}

void writeTimestamp(VkCommandBuffer cmd, const TimestampPool& pool, uint32_t slot) {
  if (!pool.pool) return;
  if (slot >= pool.count)
    throw RangeError("timestamp slot " + std::to_string(slot) + " >= " + std::to_string(pool.count));
  vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool.pool, slot);
}

std::vector<double> readTimestamps(const VulkanContext& context, const TimestampPool& pool) {
  if (!pool.pool) return {};
  // (value, availability) pairs: a slot the submission never wrote reads as unavailable instead
  // of blocking (VK_QUERY_RESULT_WAIT_BIT would wait for it forever).
  std::vector<uint64_t> raw(2 * pool.count);
  VkResult result = vkGetQueryPoolResults(context.device, pool.pool, 0, pool.count, raw.size() * sizeof(uint64_t),
                                          raw.data(), 2 * sizeof(uint64_t),
                                          VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
  if (result != VK_NOT_READY) VK_CHECK(result);  // VK_NOT_READY: some slot was not written

  std::vector<double> milliseconds(pool.count, std::nan(""));
  bool haveStart = raw[1] != 0;
  for (uint32_t i = 0; haveStart && i < pool.count; ++i) {
    if (raw[2 * i + 1] == 0) continue;
    uint64_t ticks = (raw[2 * i] - raw[0]) & pool.validMask;  // modular: survives a counter wrap
    milliseconds[i] = static_cast<double>(ticks) * pool.periodNs * 1e-6;
  }
  return milliseconds;
}

}  // namespace phongvk
