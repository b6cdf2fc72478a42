// Vulkan failures as exceptions that name the call that failed.
//
//   proceduray::vk::check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
//   try { ... } catch (const proceduray::vk::VulkanError& e) { e.result(); e.call(); }
//
// VulkanError is a std::system_error and a proceduray::Error (error.hpp), so
// `catch (const proceduray::Error&)` catches it with every other library exception.
#pragma once

#include <proceduray/config.hpp>

#include <proceduray/error.hpp>

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>
#include <system_error>

namespace proceduray::vk {

/// Spelled name of a VkResult ("VK_ERROR_DEVICE_LOST"), or its number.
PROCEDURAY_DECL std::string result_name(VkResult r);

/// The error category of VkResult codes, so VulkanError is a std::system_error.
PROCEDURAY_DECL const std::error_category& vulkan_category() noexcept;

/// A failed Vulkan call: carries the VkResult and the call's name.
class VulkanError : public std::system_error, public proceduray::Error {
 public:
  VulkanError(VkResult result, std::string call, const std::string& what)
      : std::system_error(static_cast<int>(result), vulkan_category(), what),
        m_result(result), m_call(std::move(call)) {}
  VkResult result() const noexcept { return m_result; }
  const std::string& call() const noexcept { return m_call; }
  const char* what() const noexcept override { return std::system_error::what(); }

 private:
  VkResult m_result;
  std::string m_call;
};

/// Throws VulkanError unless `result` is VK_SUCCESS; `call` names the failed function.
PROCEDURAY_DECL void check(VkResult result, const char* call, std::string_view context = {});

}  // namespace proceduray::vk

#include "proceduray/vk/error-inl.hpp"  // the bodies (config.hpp)
