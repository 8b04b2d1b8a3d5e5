// owned.h — a Vulkan object that frees itself: its handles (a plain struct: a pipeline with its
// layouts, a pool, an image with its memory and view) and the function that frees them, paired in
// one type as niagara pairs create and destroy. Buffer and TexelBuffer (resources.h) follow the same
// rule by hand; the others are Owned.
#pragma once

#include "vulkan/context.h"

#include <utility>

namespace phongvk {

// `Handles` freed by `Destroy` (which frees what is set, empties the struct, and is safe on an
// empty one) when the Owned goes, is assigned over, or is reset. Move-only; the context that made
// it (`owner`) must outlive it. The handles read as the struct's own members (pipeline.layout).
template <typename Handles, void (*Destroy)(Handles&, const VulkanContext&)>
struct Owned : Handles {
  const VulkanContext* owner = nullptr;

  Owned() = default;
  Owned(const Handles& handles, const VulkanContext& context) : Handles(handles), owner(&context) {}
  Owned(Owned&& other) noexcept
      : Handles(std::exchange(static_cast<Handles&>(other), Handles{})), owner(std::exchange(other.owner, nullptr)) {}
  Owned& operator=(Owned&& other) noexcept {
    if (this != &other) {
      reset();
      static_cast<Handles&>(*this) = std::exchange(static_cast<Handles&>(other), Handles{});
      owner = std::exchange(other.owner, nullptr);
    }
    return *this;
  }
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;
  ~Owned() { reset(); }

  // Frees the handles now; the Owned is empty after.
  void reset() {
    if (owner) Destroy(*this, *owner);
    static_cast<Handles&>(*this) = Handles{};
    owner = nullptr;
  }
};

}  // namespace phongvk
