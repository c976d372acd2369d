#pragma once
// Real spherical-harmonic basis, the one convention used everywhere in proxygi (C++ and GLSL):
// the Sloan / D3DX convention WITH the Condon-Shortley phase (so y_1^1 = -0.4886 x),
//   y_l^m = sqrt2 K_l^m cos(m phi) P_l^m(cos theta)        m > 0
//   y_l^m = sqrt2 K_l^|m| sin(|m| phi) P_l^|m|(cos theta)  m < 0
//   y_l^0 = K_l^0 P_l(cos theta),  K_l^m = sqrt((2l+1)/(4 pi) (l-|m|)!/(l+|m|)!),
// orthonormal over the unit sphere, with (theta, phi) the polar angles of the direction about +z
// (x = sin theta cos phi, y = sin theta sin phi, z = cos theta). Directions are world-space unit
// vectors as they are (proxygi's +Y up does not enter the basis).
// Coefficient index i = l(l+1) + m. "Order n" = bands 0..n-1 = n*n coefficients.
// The evaluators come from src/sh/codegen/generate_sh.py (generated/sh/basis_generated.h, and
// generated/sh/sh_basis.glsl with sh_eval_basis_<n>(vec3 dir, out float basis[n*n]) for GLSL).
#include <span>

#include <glm/glm.hpp>

#include "sh/basis_generated.h"

namespace proxygi::sh {

inline constexpr int kMinOrder = 1;
inline constexpr int kMaxOrder = generated::kMaxBasisOrder;  // 8

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kSqrtFourPi = 3.54490770181103205;   // DC coefficient of the constant 1
inline constexpr double kInvSqrtFourPi = 0.28209479177387814;  // y_0^0

constexpr int coefficient_count(int order) { return order * order; }
constexpr int coefficient_index(int l, int m) { return l * (l + 1) + m; }
// Band l of coefficient index i.
int band_of_index(int index);

// Fixed-order evaluation (the fast path): out must hold Order*Order values; dir must be unit.
template <int Order, class Real>
inline void evaluate_basis(const glm::vec<3, Real>& dir, Real* out) {
  static_assert(Order >= kMinOrder && Order <= kMaxOrder, "SH order out of range");
  if constexpr (Order == 1) generated::eval_basis_1(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 2) generated::eval_basis_2(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 3) generated::eval_basis_3(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 4) generated::eval_basis_4(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 5) generated::eval_basis_5(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 6) generated::eval_basis_6(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 7) generated::eval_basis_7(dir.x, dir.y, dir.z, out);
  if constexpr (Order == 8) generated::eval_basis_8(dir.x, dir.y, dir.z, out);
}

// Runtime order (1..8); out.size() must be >= order*order.
void evaluate_basis(int order, const glm::vec3& dir, std::span<float> out);
void evaluate_basis(int order, const glm::dvec3& dir, std::span<double> out);

// Reference definitions, slow, for tests: the associated Legendre function P_l^m(x) with the
// Condon-Shortley phase (standard three-term recurrence, m >= 0) and y_l^m(theta, phi) straight
// from the formula above.
double associated_legendre(int l, int m, double x);
double basis_from_definition(int l, int m, double theta, double phi);
// Legendre polynomial P_l(x).
double legendre(int l, double x);

}  // namespace proxygi::sh
