// One descriptor set with its layout and pool, made from a list of bindings.
//
//   proceduray::vk::DescriptorSet set(ctx, {{0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR},
//                                           {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}});
//   set.write(0, tlas);
//   set.write(1, image);
//   set.layout();   // for the pipeline layout
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/vk/acceleration.hpp>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <vector>

namespace proceduray::vk {

/// Every ray-tracing stage; the default visibility of a binding.
inline constexpr VkShaderStageFlags all_ray_tracing_stages =
    VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR | VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR |
    VK_SHADER_STAGE_ANY_HIT_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_CALLABLE_BIT_KHR;

/// One binding of a descriptor set.
struct Binding {
  std::uint32_t binding = 0;                        ///< layout(binding = N)
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;  ///< required
  VkShaderStageFlags stages = all_ray_tracing_stages;   ///< default: every ray-tracing stage
  std::uint32_t count = 1;                              ///< descriptors in the binding (an array past 1)
};

/// A descriptor set layout, a pool sized for it, and the one set allocated from it.
class DescriptorSet {
 public:
  DescriptorSet(const Context& ctx, std::initializer_list<Binding> bindings)
      : DescriptorSet(ctx, std::vector<Binding>(bindings)) {}
  DescriptorSet(const Context& ctx, const std::vector<Binding>& bindings);

  VkDescriptorSetLayout layout() const noexcept { return m_layout.get(); }
  VkDescriptorSet get() const noexcept { return m_set; }

  void write(std::uint32_t binding, const AccelerationStructure& tlas);
  void write(std::uint32_t binding, VkImageView storage_image);
  void write(std::uint32_t binding, const Buffer& buffer);
  /// A texture and its sampler into element `element` of a combined-image-sampler binding.
  void write(std::uint32_t binding, std::uint32_t element, VkImageView view, VkSampler sampler);

 private:
  VkDescriptorType type_of(std::uint32_t binding, const char* what) const;
  /// The common part of a one-descriptor write; throws unless the binding's type is accepted.
  VkWriteDescriptorSet write_info(std::uint32_t binding, const char* what,
                                  std::initializer_list<VkDescriptorType> accepted, const void* next = nullptr) const;

  const Context* m_ctx;
  std::map<std::uint32_t, VkDescriptorType> m_types;
  DeviceHandle<VkDescriptorSetLayout> m_layout;
  DeviceHandle<VkDescriptorPool> m_pool;  // freeing the pool frees the set
  VkDescriptorSet m_set = VK_NULL_HANDLE;
};

}  // namespace proceduray::vk

#include "proceduray/vk/descriptors-inl.hpp"  // the bodies (config.hpp)
