// The library's error vocabulary: every exception it throws is a proceduray::Error, and also
// a standard exception of the kind that says whose fault it is.
//
//   try { renderer.set_transform(pacman, 7, moved); }
//   catch (const proceduray::UsageError& e) { /* a bug in the calling code: fix the call */ }
//   catch (const proceduray::DeviceLimitError& e) { /* the scene does not fit this device */ }
//   catch (const proceduray::Error& e) { std::puts(e.what()); /* anything else the library threw */ }
//
// The hierarchy:
//   Error                                    common base (no std base of its own)
//   ├─ UsageError        : std::logic_error   bad input: unknown id, bad AABB, singular transform, ...
//   │   └─ SceneError, vk::ShaderCompileError, GlslNameError, ...
//   ├─ DeviceLimitError  : std::runtime_error a device (or Vulkan field) limit exceeded
//   ├─ EnvironmentError  : std::runtime_error a file, device or driver outside the caller's control
//   │   └─ vk::NoRayTracingDevice
//   └─ vk::VulkanError   : std::system_error  a failed Vulkan call, with its VkResult
//
// Error derives from no std exception, so `catch (const std::exception&)` stays unambiguous:
// each concrete class has exactly one std base, and what() reaches it through either base.
// Every message names the call the user made, the ids or indices passed, and the fix.
#pragma once

#include <stdexcept>
#include <string>

namespace proceduray {

/// Base of every exception the library throws; what() is the message.
class Error {
 public:
  virtual ~Error() = default;
  /// The message: the call made, the offending id or value, and the fix.
  virtual const char* what() const noexcept = 0;

 protected:
  Error() = default;
  Error(const Error&) = default;
  Error& operator=(const Error&) = default;
};

/// A bug in the calling code (bad argument, unknown id, call out of order): a std::logic_error.
class UsageError : public std::logic_error, public Error {
 public:
  explicit UsageError(const std::string& message) : std::logic_error(message) {}
  explicit UsageError(const char* message) : std::logic_error(message) {}
  const char* what() const noexcept override { return std::logic_error::what(); }
};

/// A device or Vulkan-field limit exceeded; the message names the limit, the value and the device.
class DeviceLimitError : public std::runtime_error, public Error {
 public:
  explicit DeviceLimitError(const std::string& message) : std::runtime_error(message) {}
  explicit DeviceLimitError(const char* message) : std::runtime_error(message) {}
  const char* what() const noexcept override { return std::runtime_error::what(); }
};

/// The environment failed: a file that cannot be read or written, no suitable device.
class EnvironmentError : public std::runtime_error, public Error {
 public:
  explicit EnvironmentError(const std::string& message) : std::runtime_error(message) {}
  explicit EnvironmentError(const char* message) : std::runtime_error(message) {}
  const char* what() const noexcept override { return std::runtime_error::what(); }
};

}  // namespace proceduray
