// Ground truth for any distance field a user declares: the same GLSL file compiled as C++ in
// double (shader/glsl_cpp.hpp), its declared Lipschitz bound checked by sampling before it is
// trusted, and each ray's first crossing found by a Lipschitz search plus bisection
// (ground_truth.hpp), which shares nothing with the marchers under test.
//
//   namespace acc = proceduray::accuracy;
//   const acc::FieldBounds bounds{.name = "ball", .min = glm::dvec3(-1.0), .max = glm::dvec3(1.0), .lipschitz = 1.0};
//   auto ball = [](glm::dvec3 p) { return glm::length(p) - 1.0; };   // the GLSL file's function in double
//   const acc::FieldScan scan = acc::scan_field(ball, bounds, "my tool");   // throws on NaN or a slope past L
//   acc::Result hit = acc::field_hit(ball, bounds, glm::dvec3(0.0, 0.0, -5.0), glm::dvec3(0.0, 0.0, 1.0), 0.0, 10.0);
//
// The function: the field's GLSL compiled as C++ in double, e.g. a class template that binds
// PROCEDURAY_GLSL_CPP_SCALAR(T) and includes the file (shader/glsl_cpp.hpp shows it), called as
// mine::gyroid<double>::gyroid_distance. field_bounds(field) takes the box and bound a scene
// declared (scene/field.hpp).
//
// Why a scan: the search is exact only if L bounds the slope everywhere in the box (a step of
// |f| / L then cannot cross the surface). A bound that is too small makes the truth itself
// step through thin parts, and the library would calibrate against a wrong answer. The scan
// takes, on a jittered grid of cells^3 points over the box, the central-difference gradient
// (h = 1e-6 of the box's diagonal) and the secant slope to the next point on each axis, and
// refuses the field where either exceeds L by more than 0.1%, naming the point and the slope.
// It finds what the grid sees: a slope confined to a region smaller than a cell can hide, so
// the scan is a check of the declaration, not a proof. NaN or infinity anywhere it samples is
// refused too, with the point. Runs on every core (parallel.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "proceduray/accuracy/ground_truth.hpp"
#include "proceduray/accuracy/parallel.hpp"
#include "proceduray/error.hpp"
#include "proceduray/scene/field.hpp"

namespace proceduray::accuracy {

/// A field's box (object space) and its declared Lipschitz bound, in double.
struct FieldBounds {
  std::string name;       ///< for messages
  glm::dvec3 min{-1.0};   ///< the box: the surface lies inside
  glm::dvec3 max{1.0};
  double lipschitz = 1.0; ///< the declared bound L (1 for an exact distance)
};

/// What scan_field saw: the steepest slope and where, and the evaluations it took.
struct FieldScan {
  double max_slope = 0.0;    ///< the largest gradient norm or secant slope sampled
  glm::dvec3 at{0.0};        ///< where
  std::uint64_t evaluations = 0;
  std::uint32_t points = 0;  ///< grid points sampled
};

/// The box and bound a scene declared for `f` (add_distance_field).
inline FieldBounds field_bounds(const DistanceField& f) {
  return {f.id, glm::dvec3(f.aabb.min), glm::dvec3(f.aabb.max), static_cast<double>(field_lipschitz(f))};
}

namespace detail {

inline void check_bounds(std::string_view call, const FieldBounds& b) {
  if (!finite(b.min) || !finite(b.max) || !(b.min.x < b.max.x) || !(b.min.y < b.max.y) || !(b.min.z < b.max.z)) {
    refuse(call, "field '" + b.name + "': box [" + show(b.min) + ", " + show(b.max) + "] is not finite with min < max",
           "pass finite corners, the smaller one first");
  }
  check_positive(call, "field '" + b.name + "': Lipschitz bound", b.lipschitz,
                 "declare the largest |grad f| over the box (1 for an exact distance)");
}

/// The point of cell (i, j, k) of an n^3 grid over the box, jittered within its cell by a hash
/// (the same points on every run and every schedule).
inline glm::dvec3 scan_point(const FieldBounds& b, std::uint32_t n, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  auto jitter = [](std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return (x >> 8) * (1.0 / 16777216.0);
  };
  const std::uint32_t seed = (i * 73856093u) ^ (j * 19349663u) ^ (k * 83492791u);
  const glm::dvec3 u((i + jitter(seed)) / n, (j + jitter(seed + 1u)) / n, (k + jitter(seed + 2u)) / n);
  return b.min + u * (b.max - b.min);
}

}  // namespace detail

/// Samples `distance` (double(glm::dvec3)) over the box (cells^3 jittered points, cells >= 2):
/// throws UsageError naming `call`, the field, the point and the fix for a value that is NaN or
/// infinite, or a slope above the declared bound (by more than 0.1%).
template <class Distance>
FieldScan scan_field(const Distance& distance, const FieldBounds& bounds, std::string_view call,
                     std::uint32_t cells = 24) {
  detail::check_bounds(call, bounds);
  if (cells < 2 || cells > 1024) {
    detail::refuse(call, "scan of field '" + bounds.name + "' with " + std::to_string(cells) + " cells per axis",
                   "pass 2 to 1024 (default 24)");
  }
  const double h = 1.0e-6 * glm::length(bounds.max - bounds.min);
  struct Worst {
    FieldScan scan;
    bool bad_value = false;
    glm::dvec3 bad_at{0.0};
    double bad = 0.0;
  };
  std::vector<Worst> per_worker(worker_count());
  parallel_rows(cells, [&](std::uint32_t k, std::uint32_t worker) {
    Worst& w = per_worker[worker];
    auto eval = [&](glm::dvec3 p) {
      const double v = distance(p);
      ++w.scan.evaluations;
      if (!std::isfinite(v) && !w.bad_value) {
        w.bad_value = true;
        w.bad_at = p;
        w.bad = v;
      }
      return v;
    };
    for (std::uint32_t j = 0; j < cells; ++j) {
      for (std::uint32_t i = 0; i < cells; ++i) {
        const glm::dvec3 p = detail::scan_point(bounds, cells, i, j, k);
        const double v = eval(p);
        ++w.scan.points;
        glm::dvec3 g;
        for (int a = 0; a < 3; ++a) {
          glm::dvec3 e(0.0);
          e[a] = h;
          g[a] = (eval(p + e) - eval(p - e)) / (2.0 * h);
        }
        double slope = glm::length(g);
        // Secant slopes to the next grid points: a kink the gradient misses (max, abs) shows here.
        const std::uint32_t next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& q : next) {
          if (q[0] >= cells || q[1] >= cells || q[2] >= cells) continue;
          const glm::dvec3 pq = detail::scan_point(bounds, cells, q[0], q[1], q[2]);
          slope = std::max(slope, std::abs(eval(pq) - v) / glm::length(pq - p));
        }
        if (slope > w.scan.max_slope) {
          w.scan.max_slope = slope;
          w.scan.at = p;
        }
      }
    }
  });
  FieldScan out;
  for (const Worst& w : per_worker) {  // worker order: the same report on every run
    if (w.bad_value) {
      detail::refuse(call, "field '" + bounds.name + "' is " + (std::isnan(w.bad) ? std::string("NaN") : detail::show(w.bad)) + " at " + detail::show(w.bad_at) +
                               ", inside its box",
                     "make the distance finite everywhere in the box (guard divisions, logs and roots)");
    }
    out.evaluations += w.scan.evaluations;
    out.points += w.scan.points;
    if (w.scan.max_slope > out.max_slope) {
      out.max_slope = w.scan.max_slope;
      out.at = w.scan.at;
    }
  }
  if (out.max_slope > bounds.lipschitz * 1.001) {
    detail::refuse(call, "field '" + bounds.name + "' has slope " + detail::show(out.max_slope) + " at " +
                             detail::show(out.at) + ", above its declared Lipschitz bound " +
                             detail::show(bounds.lipschitz),
                   "declare a bound of at least " + detail::show(out.max_slope) +
                       " (marches divide steps by it; too small a bound steps through the surface)");
  }
  return out;
}

/// The first crossing of origin + t dir (object space) with the field, t in [t_lo, t_hi] clipped
/// to the box: a Lipschitz search with the declared bound, then bisection (ground_truth.hpp's
/// rules and outcomes). A ray that misses the box misses. Throws UsageError as lipschitz_search.
template <class Distance>
Result field_hit(const Distance& distance, const FieldBounds& bounds, glm::dvec3 origin, glm::dvec3 dir, double t_lo,
                 double t_hi, const SearchOptions& options = {}) {
  constexpr std::string_view call = "field_hit";
  detail::check_bounds(call, bounds);
  detail::check_ray(call, origin, dir, t_lo, t_hi);
  double lo = t_lo, hi = t_hi;
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0) {
      if (origin[a] < bounds.min[a] || origin[a] > bounds.max[a]) return Result{};
      continue;
    }
    double t0 = (bounds.min[a] - origin[a]) / dir[a], t1 = (bounds.max[a] - origin[a]) / dir[a];
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  if (!(lo <= hi)) return Result{};
  return lipschitz_search(distance, bounds.lipschitz, origin, dir, lo, hi, options);
}

}  // namespace proceduray::accuracy
