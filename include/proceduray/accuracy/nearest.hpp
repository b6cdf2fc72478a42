// The ground truth of one ray over several objects: the nearest hit among their searches, unless
// a search that ran out of budget stopped in front of it (then nothing in front was ruled out,
// and the ray's answer is undetermined, never a guess).
//
//   proceduray::accuracy::NearestHit nearest;
//   nearest.add(proceduray::accuracy::Result{.outcome = proceduray::accuracy::Outcome::hit, .t = 2.0}, 1);
//   nearest.add(proceduray::accuracy::Result{.outcome = proceduray::accuracy::Outcome::miss}, 2);
//   proceduray::accuracy::Reference ref = nearest.reference();   // hit at t = 2
//   std::uint32_t object = nearest.object(0);                     // 1 (0: none, or undetermined)
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

#include "proceduray/accuracy/ground_truth.hpp"
#include "proceduray/accuracy/metrics.hpp"

namespace proceduray::accuracy {

class NearestHit {
 public:
  /// Takes one object's search along the ray.
  void add(const Result& r, std::uint32_t object) {
    if (r.outcome == Outcome::undetermined) m_doubt = std::min(m_doubt, r.t);
    if (r.outcome != Outcome::hit || !(r.t < m_nearest)) return;
    m_nearest = r.t;
    m_normal = r.normal;
    m_object = object;
  }
  /// A search stopped undecided at or before the nearest hit.
  bool undetermined() const { return m_doubt < infinity && m_doubt <= m_nearest; }
  /// The ray's reference: undetermined, the nearest hit, or a miss.
  Reference reference() const {
    if (undetermined()) return {.outcome = Outcome::undetermined, .t = 0.0, .normal = glm::dvec3(0.0)};
    if (!(m_nearest < infinity)) return {.outcome = Outcome::miss};
    return {.outcome = Outcome::hit, .t = m_nearest, .normal = m_normal};
  }
  /// The object of the nearest hit, or `none` for a miss or an undetermined ray.
  std::uint32_t object(std::uint32_t none) const {
    return undetermined() || !(m_nearest < infinity) ? none : m_object;
  }

 private:
  static constexpr double infinity = std::numeric_limits<double>::infinity();
  double m_nearest = infinity;  // nearest determined hit
  double m_doubt = infinity;    // nearest point where a search stopped undecided
  glm::dvec3 m_normal{0.0};
  std::uint32_t m_object = 0;
};

}  // namespace proceduray::accuracy
