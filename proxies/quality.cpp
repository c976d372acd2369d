#include "proxies/quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "proxies/fit.h"
#include "proxies/mesh_index.h"
#include "proxies/point_sampling.h"

namespace proxygi::proxies {

FitQuality measure_quality(const anim::Character& character, const BindSurface& surface,
                           std::span<const glm::vec4> spheres, float tolerance_m,
                           const QualityOptions& options) {
  FitQuality q;
  if (spheres.empty()) return q;
  const float diagonal = std::max(bounds_of(surface.soup.positions).diagonal(), 1e-6f);

  // Surface -> spheres.
  const std::vector<SurfaceSample> samples = sample_surface(character, surface, options.surface_samples, options.seed);
  int covered = 0;
  double sum = 0.0;
  for (const SurfaceSample& s : samples) {
    float d = std::numeric_limits<float>::max();
    for (const glm::vec4& sphere : spheres) d = std::min(d, glm::length(s.position - glm::vec3(sphere)) - sphere.w);
    d = std::max(d, 0.0f);
    covered += d <= tolerance_m ? 1 : 0;
    sum += double(d);
    q.hausdorff_surface_to_spheres = std::max(q.hausdorff_surface_to_spheres, d);
  }
  q.surface_samples = int(samples.size());
  q.coverage = samples.empty() ? 0.0f : float(covered) / float(samples.size());
  q.mean_surface_to_spheres = samples.empty() ? 0.0f : float(sum / double(samples.size()));

  // Union boundary -> surface (exact point-triangle distances).
  ClosestTriangleGrid closest;
  closest.build(surface.soup, diagonal / 50.0f);
  const std::vector<glm::vec3> directions = fibonacci_directions(options.boundary_points_per_sphere);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const glm::vec3 c(spheres[i]);
    for (const glm::vec3& d : directions) {
      const glm::vec3 p = c + spheres[i].w * d;
      bool hidden = false;
      for (std::size_t j = 0; j < spheres.size() && !hidden; ++j)
        hidden = j != i && glm::length(p - glm::vec3(spheres[j])) < spheres[j].w;
      if (hidden) continue;
      q.hausdorff_spheres_to_surface = std::max(q.hausdorff_spheres_to_surface, closest.distance(p, 2.0f * diagonal));
    }
  }

  // Outside volume of the union (Monte Carlo, uniform in the union).
  WindingIndex winding;
  winding.build(surface.soup, 64);
  std::vector<double> cdf(spheres.size());
  double total = 0.0;
  for (std::size_t i = 0; i < spheres.size(); ++i) cdf[i] = (total += double(spheres[i].w) * spheres[i].w * spheres[i].w);
  Random random(options.seed + 1);
  int kept = 0, outside = 0;
  for (int attempt = 0; kept < options.volume_samples && attempt < 50 * options.volume_samples; ++attempt) {
    const double target = double(random.uniform()) * total;
    const std::size_t i = std::min(std::size_t(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin()), spheres.size() - 1);
    glm::vec3 u;
    do u = glm::vec3(random.uniform(), random.uniform(), random.uniform()) * 2.0f - 1.0f;
    while (glm::dot(u, u) > 1.0f);
    const glm::vec3 p = glm::vec3(spheres[i]) + spheres[i].w * u;
    int containing = 0;
    for (const glm::vec4& sphere : spheres) containing += glm::length(p - glm::vec3(sphere)) <= sphere.w ? 1 : 0;
    if (random.uniform() * float(std::max(containing, 1)) >= 1.0f) continue;
    ++kept;
    outside += winding.inside(p) ? 0 : 1;
  }
  q.volume_samples = kept;
  q.outside_volume_ratio = kept > 0 ? float(outside) / float(kept) : 0.0f;
  return q;
}

FitQuality measure_fit_quality(const anim::Character& character, const FitResult& fit) {
  std::vector<glm::vec4> spheres;
  for (const FittedSphere& sphere : fit.fitted) spheres.emplace_back(sphere.center, sphere.radius);
  return measure_quality(character, fit.surface, spheres, fit.tolerance_m);
}

}  // namespace proxygi::proxies
