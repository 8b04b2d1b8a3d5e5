// gltf_accessor.h — a glTF accessor's elements read as numbers: from its buffer view, with every
// range checked against the view and the buffer once, up front (a file whose offsets, strides or
// counts lie is an error, not a read out of bounds), or from values a decoder made
// (KHR_draco_mesh_compression, gltf_draco.h).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace phongvk {

// glTF's component types (the specification's GL enums).
enum GltfComponentType : int {
  GLTF_BYTE = 5120,
  GLTF_UNSIGNED_BYTE = 5121,
  GLTF_SHORT = 5122,
  GLTF_UNSIGNED_SHORT = 5123,
  GLTF_UNSIGNED_INT = 5125,
  GLTF_FLOAT = 5126,
  GLTF_DOUBLE = 5130,  // not glTF 2.0's, but tinygltf's
};

class Accessor {
 public:
  // Accessor `index` of `model`, named `what` in messages ("NORMAL"). Throws SceneError
  // "<where>: <path>: <what> (accessor <index>): <why>" for one that does not exist, is sparse, has
  // no buffer view, an unknown type, or runs past its view or its buffer.
  Accessor(const tinygltf::Model& model, int index, const std::string& what, const std::string& path, const std::string& where);
  // `count` elements of `components` values of `componentType` (GLTF_FLOAT or GLTF_UNSIGNED_INT),
  // packed at `data`, which must outlive the accessor.
  Accessor(const void* data, size_t count, int components, int componentType);

  size_t count() const { return count_; }
  int components() const { return components_; }

  // Component c of element i (i < count()): integers as they are, or scaled to [0, 1] ([-1, 1]
  // signed) where the accessor is normalized.
  double at(size_t i, int c) const {
    const unsigned char* p = data_ + i * stride_ + size_t(c) * size_t(componentSize_);
    switch (componentType_) {
      case GLTF_FLOAT: return read<float>(p);
      case GLTF_UNSIGNED_BYTE: return scaled(read<uint8_t>(p), 255.0);
      case GLTF_UNSIGNED_SHORT: return scaled(read<uint16_t>(p), 65535.0);
      case GLTF_UNSIGNED_INT: return read<uint32_t>(p);
      case GLTF_BYTE: return scaled(read<int8_t>(p), 127.0);
      case GLTF_SHORT: return scaled(read<int16_t>(p), 32767.0);
      default: return NAN;
    }
  }

  bool isInteger() const { return componentType_ != GLTF_FLOAT && componentType_ != GLTF_DOUBLE; }
  bool isUnsignedInteger() const {
    return componentType_ == GLTF_UNSIGNED_BYTE || componentType_ == GLTF_UNSIGNED_SHORT || componentType_ == GLTF_UNSIGNED_INT;
  }

 private:
  template <typename T>
  static double read(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return double(value);
  }
  double scaled(double value, double max) const { return normalized_ ? std::fmax(value / max, -1.0) : value; }

  const unsigned char* data_ = nullptr;
  size_t count_ = 0, stride_ = 0;
  int components_ = 0, componentSize_ = 0, componentType_ = 0;
  bool normalized_ = false;
};

}  // namespace phongvk
