#pragma once
// Convolution with zonal kernels, the clamped cosine, H(N) and the ringing window
// (conventions in sh/basis.h).
//
// Convolving f with a kernel symmetric about +z with zonal coefficients k_l (paper eq. 7):
//   (f * k)_lm = sqrt(4 pi / (2l + 1)) k_l f_lm.
// The clamped cosine max(cos theta, 0) has h_l = sqrt(pi)/2, sqrt(pi/3), sqrt(5 pi)/8, 0,
// -sqrt(pi)/16, 0, sqrt(13 pi)/128, 0; its convolution factors A_l = sqrt(4pi/(2l+1)) h_l are
// pi, 2pi/3, pi/4, 0, -pi/24, 0, pi/64, 0. Irradiance E(N) = sum_lm A_l L_lm y_lm(N) (not / pi).
// H(N) = rot(h, N): the SH vector of max(N . s, 0), so E(N) = H(N) . L.
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace proxygi::sh {

// Zonal coefficients h_l of the clamped cosine, l = 0..order-1 (closed form).
std::vector<double> clamped_cosine_zonal(int order);

// In place: sh_lm *= sqrt(4 pi / (2l + 1)) kernel_l. sh.size() >= order*order, kernel >= order.
void convolve_zonal(int order, std::span<const double> kernel, std::span<double> sh);
void convolve_zonal(int order, std::span<const double> kernel, std::span<float> sh);

// H(N): SH vector (order*order values) of the clamped cosine about the unit normal N.
std::vector<double> clamped_cosine_about(int order, const glm::dvec3& normal);

// Ringing window w_l = cos(pi l / (2 h)) for l = 0..order-1; the SHEXP authors suggest
// h = 2 * order (the default when window_size <= 0). Bands with l >= h get 0.
std::vector<double> ringing_window(int order, double window_size = 0.0);
// In place: sh_lm *= w_l.
void apply_ringing_window(int order, std::span<float> sh, double window_size = 0.0);
void apply_ringing_window(int order, std::span<double> sh, double window_size = 0.0);

}  // namespace proxygi::sh
