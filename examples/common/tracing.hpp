// How an example scene traces its secondary rays: nested in closest-hit shaders, or in a loop
// from raygen (portable: every ray at recursion depth 1).
//
//   const examples::Tracing mode = examples::Tracing::iterative;   // paper::PaperScene({}, mode) runs at depth 1
//
// Why both: recursion reads naturally and is what the report and the D3D12 sample do, but
// Vulkan guarantees a maxRayRecursionDepth of only 1, and a deep recursion's stack costs every
// ray. Iterative tracing returns what raygen needs in the payload (the unshadowed light term,
// the shadow ray's and the reflection's origin and directions, the reflection's share) and
// raygen traces them; the pixel is the same sum, local (1 - f) + f reflected, level by level.
#pragma once

namespace examples {

enum class Tracing { recursive, iterative };

}  // namespace examples
