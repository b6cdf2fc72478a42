// The bodies of proceduray/vk/descriptors.hpp, compiled in every file that includes it (header-only,
// the default) or once, by implementation.hpp, in a PROCEDURAY_SEPARATE program (config.hpp).
// Include the header, never this file.
#pragma once

#include "proceduray/vk/descriptors.hpp"

#if PROCEDURAY_BODIES
namespace proceduray::vk {

PROCEDURAY_DECL DescriptorSet::DescriptorSet(const Context& ctx, const std::vector<Binding>& bindings) : m_ctx(&ctx) {
  std::vector<VkDescriptorSetLayoutBinding> described;
  std::map<VkDescriptorType, std::uint32_t> counts;
  for (const Binding& b : bindings) {
    if (!m_types.emplace(b.binding, b.type).second) {
      throw UsageError("DescriptorSet: binding " + std::to_string(b.binding) +
                       " is listed twice; give each binding its own number");
    }
    described.push_back({b.binding, b.type, b.count, b.stages, nullptr});
    counts[b.type] += b.count;
  }
  auto info = make<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  info.bindingCount = static_cast<std::uint32_t>(described.size());
  info.pBindings = described.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(ctx.device(), &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
  m_layout = own(ctx, layout, vkDestroyDescriptorSetLayout);

  std::vector<VkDescriptorPoolSize> sizes;
  for (auto [type, count] : counts) sizes.push_back({type, count});
  auto pool_info = make<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(ctx.device(), &pool_info, nullptr, &pool), "vkCreateDescriptorPool");
  m_pool = own(ctx, pool, vkDestroyDescriptorPool);

  auto alloc = make<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  alloc.descriptorPool = pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  check(vkAllocateDescriptorSets(ctx.device(), &alloc, &m_set), "vkAllocateDescriptorSets");
}

PROCEDURAY_DECL VkDescriptorType DescriptorSet::type_of(std::uint32_t binding, const char* what) const {
  auto it = m_types.find(binding);
  if (it == m_types.end()) {
    throw UsageError(std::string("DescriptorSet::write: binding ") + std::to_string(binding) +
                     " does not exist in this set; write " + what + " to a binding the set was made with");
  }
  return it->second;
}

PROCEDURAY_DECL VkWriteDescriptorSet DescriptorSet::write_info(std::uint32_t binding, const char* what,
                                                              std::initializer_list<VkDescriptorType> accepted,
                                                              const void* next) const {
  const VkDescriptorType type = type_of(binding, what);
  if (std::find(accepted.begin(), accepted.end(), type) == accepted.end()) {
    throw UsageError("DescriptorSet::write: binding " + std::to_string(binding) + " cannot hold " + what +
                     "; write it to a binding of that type");
  }
  auto write = make<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, next);
  write.dstSet = m_set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  return write;
}

PROCEDURAY_DECL void DescriptorSet::write(std::uint32_t binding, const AccelerationStructure& tlas) {
  VkAccelerationStructureKHR handle = tlas.get();
  auto as = make<VkWriteDescriptorSetAccelerationStructureKHR>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR);
  as.accelerationStructureCount = 1;
  as.pAccelerationStructures = &handle;
  const auto write = write_info(binding, "an acceleration structure", {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR}, &as);
  vkUpdateDescriptorSets(m_ctx->device(), 1, &write, 0, nullptr);
}

PROCEDURAY_DECL void DescriptorSet::write(std::uint32_t binding, VkImageView storage_image) {
  const VkDescriptorImageInfo image{VK_NULL_HANDLE, storage_image, VK_IMAGE_LAYOUT_GENERAL};
  auto write = write_info(binding, "a storage image", {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(m_ctx->device(), 1, &write, 0, nullptr);
}

PROCEDURAY_DECL void DescriptorSet::write(std::uint32_t binding, std::uint32_t element, VkImageView view,
                                          VkSampler sampler) {
  const VkDescriptorImageInfo image{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  auto write = write_info(binding, "a texture", {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  write.dstArrayElement = element;
  write.pImageInfo = &image;
  vkUpdateDescriptorSets(m_ctx->device(), 1, &write, 0, nullptr);
}

PROCEDURAY_DECL void DescriptorSet::write(std::uint32_t binding, const Buffer& buffer) {
  const VkDescriptorBufferInfo info{buffer.get(), 0, VK_WHOLE_SIZE};
  auto write = write_info(binding, "a buffer", {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(m_ctx->device(), 1, &write, 0, nullptr);
}

}  // namespace proceduray::vk
#endif  // PROCEDURAY_BODIES
