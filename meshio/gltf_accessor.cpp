// gltf_accessor.cpp — see gltf_accessor.h.
#include "meshio/gltf_accessor.h"

#include "phongvk/errors.h"

#include <tiny_gltf.h>

namespace phongvk {

Accessor::Accessor(const tinygltf::Model& model, int index, const std::string& what, const std::string& path,
                   const std::string& where) {
  const auto bad = [&](const std::string& why) {
    throw SceneError(where + ": " + path + ": " + what + " (accessor " + std::to_string(index) + "): " + why);
  };
  if (index < 0 || size_t(index) >= model.accessors.size()) bad("does not exist");
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse) bad("sparse accessors are not supported");
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) bad("has no buffer view");
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) bad("its buffer does not exist");
  const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
  components_ = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  componentSize_ = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (components_ <= 0 || componentSize_ <= 0) bad("unknown type or component type");
  componentType_ = a.componentType;
  normalized_ = a.normalized;
  count_ = a.count;
  const size_t element = size_t(components_) * size_t(componentSize_);
  stride_ = view.byteStride != 0 ? view.byteStride : element;
  if (stride_ < element) bad("its stride is smaller than an element");
  // Every sum and product below is checked before it is made: offsets and counts near 2^64
  // would otherwise wrap around and pass.
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    bad("its buffer view runs past the end of its buffer");
  if (a.byteOffset > view.byteLength) bad("runs past the end of its buffer view");
  const size_t room = view.byteLength - a.byteOffset;  // bytes from the accessor's start to the view's end
  if (count_ > 0 && (element > room || count_ - 1 > (room - element) / stride_))
    bad("runs past the end of its buffer view (" + std::to_string(count_) + " elements)");
  const size_t start = view.byteOffset + a.byteOffset;
  data_ = buffer.data() + start;
}

Accessor::Accessor(const void* data, size_t count, int components, int componentType)
    : data_(static_cast<const unsigned char*>(data)), count_(count), components_(components), componentType_(componentType) {
  componentSize_ = 4;  // float or uint32
  stride_ = size_t(components) * 4;
}

}  // namespace phongvk
