// pipelines.h — compute pipelines from embedded SPIR-V, and their descriptor sets.
//
//   #include "shaders/selftest_atomic64.spv.h"
//   const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
//   ComputePipeline pipeline = createComputePipeline(context, spirv_selftest_atomic64,
//                                                    sizeof(spirv_selftest_atomic64), bindings, 4, {});
#pragma once

#include "shaders/shared.h"
#include "vulkan/context.h"
#include "vulkan/owned.h"
#include "vulkan/resources.h"

#include <span>
#include <vector>

namespace phongvk {

// One descriptor of the pipeline's single set (set = 0), visible to the compute stage.
struct Binding {
  uint32_t binding;
  VkDescriptorType type;
};

// Every descriptor of the shared set (shaders/shared.h's table, with its types), in binding order.
#define PHONGVK_AS_BINDING(name, binding, type) Binding{gpu::name, VK_DESCRIPTOR_TYPE_##type},
inline constexpr Binding SHARED_BINDINGS[] = {PHONGVK_BINDINGS(PHONGVK_AS_BINDING)};
#undef PHONGVK_AS_BINDING

// The table's entry for binding `number` (a shaders/shared.h BINDING_*).
constexpr Binding sharedBinding(uint32_t number) {
  for (const Binding& b : SHARED_BINDINGS) {
    if (b.binding == number) return b;
  }
  return {number, VK_DESCRIPTOR_TYPE_MAX_ENUM};
}

// The shared set as the context's shaders declare it: where the context reads its arrays from
// storage buffers (VulkanContext::storageArrays) every texel binding is one. Indexed by binding number.
std::vector<Binding> sharedBindings(const VulkanContext& context);

// A specialization constant: `layout(constant_id = SPEC_X) const uint NAME = default;` in GLSL,
// the id from shaders/shared.h's table.
struct SpecConstant {
  uint32_t id;
  uint32_t value;
};

// The VkSpecializationInfo of some constants, with the storage it points into.
class Specialization {
 public:
  explicit Specialization(std::span<const SpecConstant> specs);
  // Null when there are no constants.
  const VkSpecializationInfo* info() const { return entries_.empty() ? nullptr : &info_; }

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<uint32_t> values_;
  VkSpecializationInfo info_ = {};
};

// A shader module from SPIR-V (a glslang --vn array). The caller destroys it.
VkShaderModule createShaderModule(const VulkanContext& context, std::span<const uint32_t> spirv);

struct ComputePipelineHandles {
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
};

// Safe on empty handles.
void destroyComputePipeline(ComputePipelineHandles& pipeline, const VulkanContext& context);

// A compute pipeline and its layouts, freed when it goes (owned.h). Code that only records with
// one takes its handles (ComputePipelineHandles), which copy.
using ComputePipeline = Owned<ComputePipelineHandles, destroyComputePipeline>;

// `spirv` is the glslang --vn array and `spirvBytes` its sizeof. The shader's entry point is
// "main"; push constants (if pushConstantBytes > 0) start at offset 0.
ComputePipeline createComputePipeline(const VulkanContext& context, const uint32_t* spirv, size_t spirvBytes,
                                      std::span<const Binding> bindings, uint32_t pushConstantBytes,
                                      std::span<const SpecConstant> specs);

// The layout of a single descriptor set holding `bindings`, visible to `stages`.
VkDescriptorSetLayout createSetLayout(const VulkanContext& context, std::span<const Binding> bindings,
                                      VkShaderStageFlags stages);

struct DescriptorArenaHandles {
  VkDescriptorPool pool = VK_NULL_HANDLE;
};
void destroyDescriptorArena(DescriptorArenaHandles& arena, const VulkanContext& context);
// A descriptor pool for a renderer's few sets, freed (its sets with it) when it goes.
using DescriptorArena = Owned<DescriptorArenaHandles, destroyDescriptorArena>;

// Room for `maxSets` sets with up to `maxBuffersPerSet` storage, uniform and texel buffers each.
void createDescriptorArena(DescriptorArena& result, const VulkanContext& context, uint32_t maxSets,
                           uint32_t maxBuffersPerSet = 16);

// One buffer descriptor to write; range VK_WHOLE_SIZE means from offset to the buffer's end. A
// uniform texel buffer descriptor is written from `view` instead (texelDescriptor below).
struct BufferDescriptor {
  uint32_t binding;
  VkDescriptorType type;
  VkBuffer buffer;
  VkDeviceSize offset = 0;
  VkDeviceSize range = VK_WHOLE_SIZE;
  VkBufferView view = VK_NULL_HANDLE;
};

// The descriptor of `buffer` at shared binding `binding`, of the table's type.
inline BufferDescriptor bufferDescriptor(uint32_t binding, const Buffer& buffer) {
  return {binding, sharedBinding(binding).type, buffer.buffer};
}

// The descriptor of `texels` at `binding` (of sharedBindings' table, or another of the caller's):
// its texel view for a texel binding, the buffer itself for a storage binding (a pass that writes
// what others read as texels, or the 32-bit key path).
inline BufferDescriptor texelDescriptor(const Binding& binding, const TexelBuffer& texels) {
  return {binding.binding, binding.type, texels.buffer.buffer, 0, VK_WHOLE_SIZE, texels.view};
}

// Allocates a set of `setLayout` from the arena and writes `descriptors` into it.
VkDescriptorSet allocateDescriptorSet(const VulkanContext& context, const DescriptorArena& arena,
                                      VkDescriptorSetLayout setLayout, std::span<const BufferDescriptor> descriptors);

// Workgroups needed to cover `threads` invocations with `groupSize` per group (rounds up).
uint32_t groupCount(uint32_t threads, uint32_t groupSize);

}  // namespace phongvk
