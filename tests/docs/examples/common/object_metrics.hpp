#include "examples/common/object_metrics.hpp"

// @declarations
void usage(const proceduray::accuracy::Frame& frame, const std::vector<proceduray::accuracy::Reference>& pixels,
           const std::vector<proceduray::accuracy::Sample>& samples, const std::vector<std::uint32_t>& truth_ids,
           const std::vector<std::uint32_t>& seen) {
  struct {
    proceduray::accuracy::Frame frame() const { return f; }
    proceduray::accuracy::Frame f;
    const std::vector<proceduray::accuracy::Reference>& pixels;
  } truth{frame, pixels};
  // @statements
  (void)m;
  (void)steps;
  (void)all;
}
