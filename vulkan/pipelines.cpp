// pipelines.cpp — shader modules, compute pipelines, descriptor sets.
#include "vulkan/pipelines.h"

#include "vulkan/vk_check.h"

#include <cassert>
#include <vector>

namespace phongvk {
namespace {

VkPipelineLayout createPipelineLayout(const VulkanContext& context, VkDescriptorSetLayout setLayout,
                                      uint32_t pushConstantBytes) {
  VkPushConstantRange pushConstants = {VK_SHADER_STAGE_COMPUTE_BIT, 0, pushConstantBytes};
  VkPipelineLayoutCreateInfo info = { VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO };
  info.setLayoutCount = 1;
  info.pSetLayouts = &setLayout;
  info.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
  info.pPushConstantRanges = &pushConstants;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(context.device, &info, nullptr, &layout));
  return layout;
}

VkPipeline createPipeline(const VulkanContext& context, VkShaderModule module, VkPipelineLayout layout,
                          std::span<const SpecConstant> specs) {
  const Specialization specialization(specs);
  VkComputePipelineCreateInfo info = { VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO };
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = specialization.info();
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateComputePipelines(context.device, context.pipelineCache, 1, &info, nullptr, &pipeline));
  return pipeline;
}

}  // namespace

Specialization::Specialization(std::span<const SpecConstant> specs) {
  for (const SpecConstant& spec : specs) {
    entries_.push_back({spec.id, static_cast<uint32_t>(values_.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values_.push_back(spec.value);
  }
  info_.mapEntryCount = static_cast<uint32_t>(entries_.size());
  info_.pMapEntries = entries_.data();
  info_.dataSize = values_.size() * sizeof(uint32_t);
  info_.pData = values_.data();
}

VkShaderModule createShaderModule(const VulkanContext& context, std::span<const uint32_t> spirv) {
  assert(!spirv.empty());
  VkShaderModuleCreateInfo info = { VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO };
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(context.device, &info, nullptr, &module));
  return module;
}

VkDescriptorSetLayout createSetLayout(const VulkanContext& context, std::span<const Binding> bindings,
                                      VkShaderStageFlags stages) {
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const Binding& binding : bindings) {
    VkDescriptorSetLayoutBinding layoutBinding = {};
    layoutBinding.binding = binding.binding;
    layoutBinding.descriptorType = binding.type;
    layoutBinding.descriptorCount = 1;
    layoutBinding.stageFlags = stages;
    layoutBindings.push_back(layoutBinding);
  }
  VkDescriptorSetLayoutCreateInfo info = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO };
  info.bindingCount = static_cast<uint32_t>(layoutBindings.size());
  info.pBindings = layoutBindings.data();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(context.device, &info, nullptr, &setLayout));
  return setLayout;
}


ComputePipeline createComputePipeline(const VulkanContext& context, const uint32_t* spirv, size_t spirvBytes,
                                      std::span<const Binding> bindings, uint32_t pushConstantBytes,
                                      std::span<const SpecConstant> specs) {
  ComputePipeline result({}, context);  // what is made is freed if a later step throws
  VkShaderModule module = VK_NULL_HANDLE;
  try {
    result.setLayout = createSetLayout(context, bindings, VK_SHADER_STAGE_COMPUTE_BIT);
    result.layout = createPipelineLayout(context, result.setLayout, pushConstantBytes);
    module = createShaderModule(context, {spirv, spirvBytes / sizeof(uint32_t)});
    result.pipeline = createPipeline(context, module, result.layout, specs);
  } catch (...) {
    if (module) vkDestroyShaderModule(context.device, module, nullptr);
    throw;
  }
  // The pipeline keeps its own compiled copy; the module is only needed to create it.
  vkDestroyShaderModule(context.device, module, nullptr);
  return result;
}

void destroyComputePipeline(ComputePipelineHandles& pipeline, const VulkanContext& context) {
  if (pipeline.pipeline) vkDestroyPipeline(context.device, pipeline.pipeline, nullptr);
  if (pipeline.layout) vkDestroyPipelineLayout(context.device, pipeline.layout, nullptr);
  if (pipeline.setLayout) vkDestroyDescriptorSetLayout(context.device, pipeline.setLayout, nullptr);
  pipeline = {};
}

void createDescriptorArena(DescriptorArena& result, const VulkanContext& context, uint32_t maxSets,
                           uint32_t maxBuffersPerSet) {
  VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, maxSets * maxBuffersPerSet},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, maxSets * maxBuffersPerSet},
      {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, maxSets * maxBuffersPerSet},
  };
  VkDescriptorPoolCreateInfo info = { VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO };
  info.maxSets = maxSets;
  info.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
  info.pPoolSizes = sizes;
  result = DescriptorArena({}, context);
  VK_CHECK(vkCreateDescriptorPool(context.device, &info, nullptr, &result.pool));
}

void destroyDescriptorArena(DescriptorArenaHandles& arena, const VulkanContext& context) {
  if (arena.pool) vkDestroyDescriptorPool(context.device, arena.pool, nullptr);
  arena = {};
}

VkDescriptorSet allocateDescriptorSet(const VulkanContext& context, const DescriptorArena& arena,
                                      VkDescriptorSetLayout setLayout, std::span<const BufferDescriptor> descriptors) {
  VkDescriptorSetAllocateInfo allocateInfo = { VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO };
  allocateInfo.descriptorPool = arena.pool;
  allocateInfo.descriptorSetCount = 1;
  allocateInfo.pSetLayouts = &setLayout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateDescriptorSets(context.device, &allocateInfo, &set));

  // Filled completely before any write points into it: push_back would move the buffer infos.
  std::vector<VkDescriptorBufferInfo> bufferInfos;
  for (const BufferDescriptor& descriptor : descriptors)
    bufferInfos.push_back({descriptor.buffer, descriptor.offset, descriptor.range});
  std::vector<VkWriteDescriptorSet> writes;
  for (size_t i = 0; i < descriptors.size(); ++i) {
    VkWriteDescriptorSet write = { VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET };
    write.dstSet = set;
    write.dstBinding = descriptors[i].binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptors[i].type;
    if (descriptors[i].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) {
      write.pTexelBufferView = &descriptors[i].view;
    } else {
      write.pBufferInfo = &bufferInfos[i];
    }
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(context.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return set;
}

std::vector<Binding> sharedBindings(const VulkanContext& context) {
  std::vector<Binding> bindings(std::begin(SHARED_BINDINGS), std::end(SHARED_BINDINGS));
  for (Binding& b : bindings) {
    if (context.storageArrays && b.type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  }
  return bindings;
}

uint32_t groupCount(uint32_t threads, uint32_t groupSize) {
  assert(groupSize > 0);
  return threads / groupSize + (threads % groupSize != 0);  // no overflow near UINT32_MAX
}

}  // namespace phongvk
