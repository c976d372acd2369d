#pragma once
// CPU twin of the exact indirect operator (paper eq. 16/17, order 3) as the exact variant of
// indirect.comp evaluates it for one proxy at one receiver.
//
// I_c = R⁻¹ M(s) R L̃_c is the proxy's radiance vector (×π/albedo) for colour channel c, with R
// any rotation taking the proxy direction d̂ to +z (M(s) commutes with rotations about z). The
// receiver needs only H(N) · I_c = H(R N)ᵀ M(s) (R L̃_c) = W · L̃_c with
//   w = M(s)ᵀ H(R N)   (canonical frame; H = clamped cosine rotated to R N)
//   W = R_sh⁻¹ w       (back in world space: W(ω) = w(R ω))
// so one 9-vector is rotated per proxy instead of three lighting vectors.
//
// The rotation R has rows (b1, b2, d̂), the branchless orthonormal basis of Duff et al. 2017
// ("Building an orthonormal basis, revisited"), b1 × b2 = d̂. The SH rotation of W is done band
// by band: band 0 is invariant; band 1 is the 3×3 rotation itself (y_1m are linear in the
// direction); band 2 evaluates w's band 2 at R ω_k for five fixed world directions ω_k and
// re-projects with the constant inverse of the 5×5 matrix y_2m(ω_k) ("evaluate at directions and
// solve", Sloan's Stupid SH Tricks). With ω = x, z, (x+y)/√2, (x+z)/√2, (y+z)/√2 that inverse is
// sparse and written out in closed form.
//
// M(s) comes from sh::ExactIndirectTable (row-major M_jk, rows over s, linearly interpolated
// like every other frame table, element by element, at s (rows − 1)). The canonical proxy is
// symmetric about z and under mirrors through z, so M_jk = 0 unless j and k have the same m: only
// the 19 entries of kExactIndirectEntries are read (the rest are zero to rounding; render_tests
// checks the table).
#include <array>

#include <glm/glm.hpp>

#include "sh/indirect.h"

namespace proxygi::render {

// Flat indices j * 9 + k of the entries of M(s) with m_j = m_k (order 3): m = 0 couples
// coefficients 0, 2, 6; m = −1: 1, 5; m = 1: 3, 7; m = −2: 4; m = 2: 8.
inline constexpr int kExactIndirectEntries[19] = {0,  2,  6,  18, 20, 24, 54, 56, 60, 10,
                                                  14, 46, 50, 30, 34, 66, 70, 40, 80};

// W (order 3, world frame) with W · L̃_c = H(N) · I_c for the proxy seen in unit direction
// `direction` with s = sin θ. normal must be unit. The table must be order 3.
std::array<float, 9> exact_indirect_weights(const sh::ExactIndirectTable& table, float s, const glm::vec3& direction,
                                            const glm::vec3& normal);

// Rows (b1, b2, d̂) of the rotation taking d̂ to +z (Duff et al. 2017); d̂ unit.
std::array<glm::vec3, 3> rotation_to_z(const glm::vec3& direction);

}  // namespace proxygi::render
