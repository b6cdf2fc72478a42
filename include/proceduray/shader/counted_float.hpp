// A float that counts its arithmetic: run a primitive's C++ mirror (the GLSL compiled as C++,
// glsl_cpp.hpp) with it, and the count is the flops the shader does at that point, taken from
// its code rather than by hand (tools/bench/flops.cpp: flops per evaluation of the fractals).
//
//   using V3 = glm::vec<3, proceduray::CountedFloat>;
//   proceduray::CountedFloat::reset();
//   const proceduray::CountedFloat r = glm::length(V3(1.0f, 2.0f, 2.0f));   // 3
//   const std::uint64_t flops = proceduray::CountedFloat::count();         // 6: 3 *, 2 +, 1 sqrt
//
// Each +, -, *, / and each call of sqrt, inversesqrt, log, log2, exp, sin, cos, atan, pow counts
// 1 (so a * b + c counts 2, as the peak's FMAs do); comparisons, negation, abs, floor and
// conversions count nothing. The value is the float's, so the control flow is the float
// shader's. std::numeric_limits says "IEC 559 float" so that GLM's templates take it. The count
// is per thread.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace proceduray {

class CountedFloat {
 public:
  constexpr CountedFloat() = default;
  constexpr CountedFloat(float v) : m_v(v) {}  // NOLINT: literals and floats convert, as in GLSL
  explicit constexpr CountedFloat(double v) : m_v(static_cast<float>(v)) {}
  explicit constexpr CountedFloat(int v) : m_v(static_cast<float>(v)) {}
  explicit constexpr CountedFloat(unsigned v) : m_v(static_cast<float>(v)) {}
  explicit constexpr operator float() const { return m_v; }
  explicit constexpr operator unsigned() const { return static_cast<unsigned>(m_v); }
  explicit constexpr operator int() const { return static_cast<int>(m_v); }
  constexpr float value() const { return m_v; }

  static void reset() { s_count = 0; }
  static std::uint64_t count() { return s_count; }
  static CountedFloat op(float v) {
    ++s_count;
    return CountedFloat(v);
  }

 private:
  float m_v = 0.0f;
  static inline thread_local std::uint64_t s_count = 0;
};

inline CountedFloat operator+(CountedFloat a, CountedFloat b) { return CountedFloat::op(a.value() + b.value()); }
inline CountedFloat operator-(CountedFloat a, CountedFloat b) { return CountedFloat::op(a.value() - b.value()); }
inline CountedFloat operator*(CountedFloat a, CountedFloat b) { return CountedFloat::op(a.value() * b.value()); }
inline CountedFloat operator/(CountedFloat a, CountedFloat b) { return CountedFloat::op(a.value() / b.value()); }
inline CountedFloat operator-(CountedFloat a) { return CountedFloat(-a.value()); }
inline CountedFloat operator+(CountedFloat a) { return a; }
inline CountedFloat& operator+=(CountedFloat& a, CountedFloat b) { return a = a + b; }
inline CountedFloat& operator-=(CountedFloat& a, CountedFloat b) { return a = a - b; }
inline CountedFloat& operator*=(CountedFloat& a, CountedFloat b) { return a = a * b; }
inline CountedFloat& operator/=(CountedFloat& a, CountedFloat b) { return a = a / b; }
inline bool operator<(CountedFloat a, CountedFloat b) { return a.value() < b.value(); }
inline bool operator>(CountedFloat a, CountedFloat b) { return a.value() > b.value(); }
inline bool operator<=(CountedFloat a, CountedFloat b) { return a.value() <= b.value(); }
inline bool operator>=(CountedFloat a, CountedFloat b) { return a.value() >= b.value(); }
inline bool operator==(CountedFloat a, CountedFloat b) { return a.value() == b.value(); }
inline bool operator!=(CountedFloat a, CountedFloat b) { return a.value() != b.value(); }

// Found by argument-dependent lookup from GLM's templates and the mirrored GLSL.
inline CountedFloat sqrt(CountedFloat a) { return CountedFloat::op(std::sqrt(a.value())); }
inline CountedFloat inversesqrt(CountedFloat a) { return CountedFloat::op(1.0f / std::sqrt(a.value())); }
inline CountedFloat log(CountedFloat a) { return CountedFloat::op(std::log(a.value())); }
inline CountedFloat log2(CountedFloat a) { return CountedFloat::op(std::log2(a.value())); }
inline CountedFloat exp(CountedFloat a) { return CountedFloat::op(std::exp(a.value())); }
inline CountedFloat sin(CountedFloat a) { return CountedFloat::op(std::sin(a.value())); }
inline CountedFloat cos(CountedFloat a) { return CountedFloat::op(std::cos(a.value())); }
inline CountedFloat atan(CountedFloat y, CountedFloat x) { return CountedFloat::op(std::atan2(y.value(), x.value())); }
inline CountedFloat pow(CountedFloat a, CountedFloat b) { return CountedFloat::op(std::pow(a.value(), b.value())); }
inline CountedFloat abs(CountedFloat a) { return CountedFloat(std::fabs(a.value())); }
inline CountedFloat floor(CountedFloat a) { return CountedFloat(std::floor(a.value())); }

}  // namespace proceduray

template <>
struct std::numeric_limits<proceduray::CountedFloat> : std::numeric_limits<float> {};
