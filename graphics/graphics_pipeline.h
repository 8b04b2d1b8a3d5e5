// graphics_pipeline.h — what a vertex + fragment pipeline needs beside the compute port's
// infrastructure: images to draw into, a render pass that clears them and hands the colour to a
// copy, and the pipeline itself.
//
//   GraphicsLayout layout = createGraphicsLayout(context, bindings);
//   RenderPass pass = createColorDepthRenderPass(context, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT);
//   GraphicsPipeline pipeline = createGraphicsPipeline(context, {...});
// Each frees itself when it goes (vulkan/owned.h).
#pragma once

#include "vulkan/context.h"
#include "vulkan/pipelines.h"

#include <vector>
#include <span>

namespace phongvk {

struct RenderTargetHandles {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};
void destroyRenderTarget(RenderTargetHandles& target, const VulkanContext& context);
// A device-local 2D image with one mip level and a view of it, freed when it goes (owned.h).
using RenderTarget = Owned<RenderTargetHandles, destroyRenderTarget>;

// `aspect` is COLOR or DEPTH. Throws DeviceError when the device cannot use `format` for
// `usage` with optimal tiling (naming the format), VulkanError otherwise.
void createRenderTarget(RenderTarget& result, const VulkanContext& context, VkFormat format, uint32_t width,
                        uint32_t height, VkImageUsageFlags usage, VkImageAspectFlags aspect);

// One subpass drawing into a colour and a depth attachment, both cleared when it begins. The
// colour ends in TRANSFER_SRC_OPTIMAL, ready to be copied out; the depth is not stored. The
// pass's dependencies order it after the previous frame's copy and before the next copy.
struct RenderPassHandles {
  VkRenderPass pass = VK_NULL_HANDLE;
};
void destroyRenderPass(RenderPassHandles& pass, const VulkanContext& context);
using RenderPass = Owned<RenderPassHandles, destroyRenderPass>;
RenderPass createColorDepthRenderPass(const VulkanContext& context, VkFormat colorFormat, VkFormat depthFormat);

// A framebuffer and a graphics pipeline, each freed when it goes.
struct FramebufferHandles {
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
};
void destroyFramebuffer(FramebufferHandles& framebuffer, const VulkanContext& context);
using Framebuffer = Owned<FramebufferHandles, destroyFramebuffer>;
struct GraphicsPipelineHandles {
  VkPipeline pipeline = VK_NULL_HANDLE;
};
void destroyGraphicsPipeline(GraphicsPipelineHandles& pipeline, const VulkanContext& context);
using GraphicsPipeline = Owned<GraphicsPipelineHandles, destroyGraphicsPipeline>;

// The descriptor set layout (one set, every binding visible to the vertex and fragment stages)
// and the pipeline layout around it; no push constants.
struct GraphicsLayoutHandles {
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
};
void destroyGraphicsLayout(GraphicsLayoutHandles& layout, const VulkanContext& context);
using GraphicsLayout = Owned<GraphicsLayoutHandles, destroyGraphicsLayout>;

GraphicsLayout createGraphicsLayout(const VulkanContext& context, std::span<const Binding> bindings);

// A triangle-list pipeline without vertex inputs (the vertex shader pulls its data), a dynamic
// viewport and scissor, depth test and write on, and one opaque colour attachment.
struct GraphicsPipelineInfo {
  std::span<const uint32_t> vertexSpirv;
  std::span<const uint32_t> fragmentSpirv;
  std::vector<SpecConstant> specs;  // both stages get them all (a stage ignores those it lacks)
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
  VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
};

GraphicsPipeline createGraphicsPipeline(const VulkanContext& context, const GraphicsPipelineInfo& info);

}  // namespace phongvk
