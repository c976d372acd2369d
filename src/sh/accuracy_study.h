#pragma once
// The SH exponential accuracy study (notes sh-math.md section 3, paper section 5 Figure 5),
// run by `proxygi bench sh`.
//
// Exponentials: `receivers` random receivers, each seeing min..max_spheres spheres in uniform
// random directions with half-angles uniform in [min, max] degrees (full-sphere visibility, no
// normal). For every order and method the relative L2 error ||g - g_ref|| / ||g_ref|| of the SH
// visibility vector against the SH projection of the TRUE visibility (product of the sphere
// indicators, dense Gauss grid), and the cost per receiver (ns per evaluation: table lookups,
// rotations, accumulation and the exponential or products), measured in the same run.
// Methods:
//   product      O_1 * O_2 * ... * O_m, products of the projected per-sphere occlusions
//   log_exact    exp*(sum of rotated log-occlusion table rows), exact exp (eigen, double)
//   ps_4, ps_8   the same log sum, product series of degree 4 / 8 with DC isolation
//   ol           optimal linear exp with the single-sphere (a, b) table
//   hyb_0.25, hyb_1   HYB with tau = 0.25 / 1
// Indirect: relative Frobenius errors of the point-sampled and averaged operators against the
// exact one over s = sin(theta). Deterministic for a given seed.
#include <cstdint>
#include <string>
#include <vector>

namespace proxygi::sh {

struct AccuracyStudyOptions {
  int receivers = 300;
  int min_spheres = 1;
  int max_spheres = 8;
  double min_half_angle_degrees = 5.0;
  double max_half_angle_degrees = 45.0;
  std::vector<int> orders = {3, 4, 5};  // each in 3..6
  std::uint32_t seed = 2007;
  int reference_z_nodes = 200;   // Gauss nodes in z of the reference projection
  int reference_phi_samples = 400;
  int table_rows = 256;          // log-occlusion / visibility / OL table rows (as on the GPU)
  double min_timing_seconds = 0.05;  // per method and order
  std::vector<int> indirect_orders = {3, 4};
  int indirect_samples = 19;     // s = 0.05, 0.10, ..., 0.95
};

struct ExponentialMethodResult {
  std::string method;
  int order = 0;
  double mean_error = 0.0;    // relative L2, fraction (0.048 = 4.8 %)
  double median_error = 0.0;
  double p95_error = 0.0;
  double ns_per_evaluation = 0.0;
  double mean_squarings = 0.0;  // HYB only
  int max_squarings = 0;        // HYB only
};

struct IndirectOperatorRow {
  int order = 0;
  double sin_theta = 0.0;
  double point_error = 0.0;     // relative Frobenius
  double averaged_error = 0.0;
  double averaged_polynomial_error = -1.0;  // order 3 only, else -1
};

struct AccuracyStudyResult {
  AccuracyStudyOptions options;
  std::vector<ExponentialMethodResult> exponential;
  std::vector<IndirectOperatorRow> indirect;
  double mean_spheres_per_receiver = 0.0;
  double seconds = 0.0;
};

AccuracyStudyResult run_accuracy_study(const AccuracyStudyOptions& options);

}  // namespace proxygi::sh
