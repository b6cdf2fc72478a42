// What the ground truth found for one ray: shared by the searchers that compute it
// (ground_truth.hpp, closed_form.hpp) and the metrics that read it (metrics.hpp), so neither
// of those headers depends on the other.
//
//   proceduray::accuracy::Outcome o = proceduray::accuracy::Outcome::undetermined;
//   bool counted = o != proceduray::accuracy::Outcome::undetermined;   // metrics leave these out
#pragma once

namespace proceduray::accuracy {

/// hit: a boundary crossing was found; miss: none in the interval; undetermined: the search ran
/// out of its budget before it could tell (never a guess).
enum class Outcome { hit, miss, undetermined };

}  // namespace proceduray::accuracy
