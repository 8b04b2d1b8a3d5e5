// graphics_pipeline.cpp — render targets, the colour + depth render pass, graphics pipelines.
#include "graphics/graphics_pipeline.h"

#include "vulkan/vk_check.h"

#include <cassert>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// A memory type the image may use, device-local if there is one (as MemoryKind::DeviceLocal).
uint32_t imageMemoryType(const VulkanContext& context, uint32_t typeBits) {
  const VkPhysicalDeviceMemoryProperties& memory = context.memoryProperties;
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)) return i;
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if (typeBits & (1u << i)) return i;
  throw VulkanError("no memory type for an image (type bits " + std::to_string(typeBits) + ")",
                    VK_ERROR_OUT_OF_DEVICE_MEMORY);
}

void checkFormat(const VulkanContext& context, VkFormat format, VkImageUsageFlags usage) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice, format, &properties);
  const VkFormatFeatureFlags have = properties.optimalTilingFeatures;
  VkFormatFeatureFlags need = 0;
  if (usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) need |= VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
  if (usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) need |= VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
  if (usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) need |= VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
  if ((have & need) != need)
    throw DeviceError(context.info.name + " cannot render to VkFormat " + std::to_string(format) +
                             " (format features " + std::to_string(have) + ", need " + std::to_string(need) + ")");
}

void allocateImageMemory(RenderTargetHandles& target, const VulkanContext& context) {
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(context.device, target.image, &requirements);
  VkMemoryAllocateInfo info = { VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO };
  info.allocationSize = requirements.size;
  info.memoryTypeIndex = imageMemoryType(context, requirements.memoryTypeBits);
  VK_CHECK(vkAllocateMemory(context.device, &info, nullptr, &target.memory));
  VK_CHECK(vkBindImageMemory(context.device, target.image, target.memory, 0));
}

// A shader module that lives only while a pipeline is created from it.
struct ShaderModule {
  ShaderModule(const VulkanContext& context, std::span<const uint32_t> spirv) : device(context.device) {
    module = createShaderModule(context, spirv);
  }
  ~ShaderModule() { vkDestroyShaderModule(device, module, nullptr); }
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;

  VkDevice device;
  VkShaderModule module = VK_NULL_HANDLE;
};

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, VkShaderModule module,
                                            const Specialization& spec) {
  VkPipelineShaderStageCreateInfo info = { VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO };
  info.stage = stage;
  info.module = module;
  info.pName = "main";
  info.pSpecializationInfo = spec.info();
  return info;
}

// Every fixed-function state of the pipeline, kept together so the create info can point at it.
struct FixedFunctionState {
  explicit FixedFunctionState(const GraphicsPipelineInfo& info) {
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    viewport.viewportCount = 1;  // both set per frame: the image size may change
    viewport.scissorCount = 1;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = info.cullMode;
    raster.frontFace = info.frontFace;
    raster.lineWidth = 1.0f;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = info.depthCompare;
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    dynamic.dynamicStateCount = static_cast<uint32_t>(std::size(dynamicStates));
    dynamic.pDynamicStates = dynamicStates;
  }
  FixedFunctionState(const FixedFunctionState&) = delete;  // the structs point into each other
  FixedFunctionState& operator=(const FixedFunctionState&) = delete;

  VkPipelineVertexInputStateCreateInfo vertexInput = { VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO };
  VkPipelineInputAssemblyStateCreateInfo assembly = { VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO };
  VkPipelineViewportStateCreateInfo viewport = { VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO };
  VkPipelineRasterizationStateCreateInfo raster = { VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO };
  VkPipelineMultisampleStateCreateInfo multisample = { VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO };
  VkPipelineDepthStencilStateCreateInfo depth = { VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO };
  VkPipelineColorBlendAttachmentState blendAttachment = {};
  VkPipelineColorBlendStateCreateInfo blend = { VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO };
  VkDynamicState dynamicStates[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic = { VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO };
};

VkAttachmentDescription attachment(VkFormat format, VkAttachmentStoreOp store, VkImageLayout finalLayout) {
  VkAttachmentDescription a = {};
  a.format = format;
  a.samples = VK_SAMPLE_COUNT_1_BIT;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = store;
  a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // cleared anyway: the old contents may go
  a.finalLayout = finalLayout;
  return a;
}

}  // namespace

void createRenderTarget(RenderTarget& result, const VulkanContext& context, VkFormat format, uint32_t width,
                        uint32_t height, VkImageUsageFlags usage, VkImageAspectFlags aspect) {
  checkFormat(context, format, usage);
  result = RenderTarget({}, context);
  VkImageCreateInfo info = { VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO };
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  try {
    VK_CHECK(vkCreateImage(context.device, &info, nullptr, &result.image));
    allocateImageMemory(result, context);
    VkImageViewCreateInfo viewInfo = { VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO };
    viewInfo.image = result.image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format;
    viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(context.device, &viewInfo, nullptr, &result.view));
  } catch (...) {
    result.reset();
    throw;
  }
}

void destroyRenderTarget(RenderTargetHandles& target, const VulkanContext& context) {
  if (target.view) vkDestroyImageView(context.device, target.view, nullptr);
  if (target.image) vkDestroyImage(context.device, target.image, nullptr);
  if (target.memory) vkFreeMemory(context.device, target.memory, nullptr);
  target = {};
}

RenderPass createColorDepthRenderPass(const VulkanContext& context, VkFormat colorFormat, VkFormat depthFormat) {
  const VkAttachmentDescription attachments[] = {
      attachment(colorFormat, VK_ATTACHMENT_STORE_OP_STORE, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL),
      attachment(depthFormat, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
  };
  VkAttachmentReference colorRef = {0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef = {1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass = {};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pDepthStencilAttachment = &depthRef;

  const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  const VkAccessFlags attachmentWrites =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  const VkSubpassDependency dependencies[] = {
      // The clear (a write, after the layout transition) waits for the previous frame's copy out
      // and for the previous frame's depth tests.
      {VK_SUBPASS_EXTERNAL, 0, VK_PIPELINE_STAGE_TRANSFER_BIT | attachmentStages, attachmentStages,
       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, attachmentWrites | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT, 0},
      // The copy out reads what the subpass wrote.
      {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, 0},
  };

  VkRenderPassCreateInfo info = { VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO };
  info.attachmentCount = static_cast<uint32_t>(std::size(attachments));
  info.pAttachments = attachments;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<uint32_t>(std::size(dependencies));
  info.pDependencies = dependencies;
  RenderPass pass({}, context);
  VK_CHECK(vkCreateRenderPass(context.device, &info, nullptr, &pass.pass));
  return pass;
}

void destroyRenderPass(RenderPassHandles& pass, const VulkanContext& context) {
  if (pass.pass) vkDestroyRenderPass(context.device, pass.pass, nullptr);
  pass = {};
}

void destroyFramebuffer(FramebufferHandles& framebuffer, const VulkanContext& context) {
  if (framebuffer.framebuffer) vkDestroyFramebuffer(context.device, framebuffer.framebuffer, nullptr);
  framebuffer = {};
}

void destroyGraphicsPipeline(GraphicsPipelineHandles& pipeline, const VulkanContext& context) {
  if (pipeline.pipeline) vkDestroyPipeline(context.device, pipeline.pipeline, nullptr);
  pipeline = {};
}

GraphicsLayout createGraphicsLayout(const VulkanContext& context, std::span<const Binding> bindings) {
  GraphicsLayout result({}, context);  // freed if the pipeline layout fails
  result.setLayout = createSetLayout(context, bindings, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);

  VkPipelineLayoutCreateInfo layoutInfo = { VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO };
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &result.setLayout;
  VK_CHECK(vkCreatePipelineLayout(context.device, &layoutInfo, nullptr, &result.layout));
  return result;
}

void destroyGraphicsLayout(GraphicsLayoutHandles& layout, const VulkanContext& context) {
  if (layout.layout) vkDestroyPipelineLayout(context.device, layout.layout, nullptr);
  if (layout.setLayout) vkDestroyDescriptorSetLayout(context.device, layout.setLayout, nullptr);
  layout = {};
}

GraphicsPipeline createGraphicsPipeline(const VulkanContext& context, const GraphicsPipelineInfo& info) {
  const ShaderModule vertex(context, info.vertexSpirv);
  const ShaderModule fragment(context, info.fragmentSpirv);
  const Specialization spec(info.specs);
  const VkPipelineShaderStageCreateInfo stages[] = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex.module, spec),
      shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment.module, spec),
  };
  const FixedFunctionState fixed(info);

  VkGraphicsPipelineCreateInfo pipelineInfo = { VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO };
  pipelineInfo.stageCount = static_cast<uint32_t>(std::size(stages));
  pipelineInfo.pStages = stages;
  pipelineInfo.pVertexInputState = &fixed.vertexInput;
  pipelineInfo.pInputAssemblyState = &fixed.assembly;
  pipelineInfo.pViewportState = &fixed.viewport;
  pipelineInfo.pRasterizationState = &fixed.raster;
  pipelineInfo.pMultisampleState = &fixed.multisample;
  pipelineInfo.pDepthStencilState = &fixed.depth;
  pipelineInfo.pColorBlendState = &fixed.blend;
  pipelineInfo.pDynamicState = &fixed.dynamic;
  pipelineInfo.layout = info.layout;
  pipelineInfo.renderPass = info.renderPass;
  GraphicsPipeline pipeline({}, context);
  VK_CHECK(vkCreateGraphicsPipelines(context.device, context.pipelineCache, 1, &pipelineInfo, nullptr, &pipeline.pipeline));
  return pipeline;
}

}  // namespace phongvk
