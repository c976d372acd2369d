#include "proxies/sphere_set_fit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace proxygi::proxies {
namespace {

constexpr std::size_t kSearchMembers = 384;
// Assignment passes after each re-clustering (each one refits every sphere of the bone).
constexpr int kAssignIterations = 4;
// A sphere never shrinks below this share of the distance to its farthest member.
constexpr float kMinRadiusShare = 0.5f;


// The radius that brings every member within the slack: max |p − c| − slack, at least
// kMinRadiusShare of the farthest distance.
float cover_radius(std::span<const glm::vec3> points, const std::vector<std::uint32_t>& members, const glm::vec3& center,
                   const SphereObjective& objective) {
  float farthest2 = 0.0f;
  for (std::uint32_t m : members) {
    const glm::vec3 d = points[m] - center;
    farthest2 = std::max(farthest2, glm::dot(d, d));
  }
  const float farthest = std::sqrt(farthest2);
  return std::max(farthest - objective.slack, kMinRadiusShare * farthest);
}

glm::vec3 centroid_of(std::span<const glm::vec3> points, const std::vector<std::uint32_t>& members) {
  glm::dvec3 sum(0.0);
  for (std::uint32_t m : members) sum += glm::dvec3(points[m]);
  return glm::vec3(sum / double(std::max<std::size_t>(members.size(), 1)));
}

// Largest-variance direction of the members (power iteration on the covariance).
glm::vec3 principal_axis(std::span<const glm::vec3> points, const std::vector<std::uint32_t>& members,
                         const glm::vec3& mean) {
  glm::dmat3 cov(0.0);
  for (std::uint32_t m : members) {
    const glm::dvec3 d = glm::dvec3(points[m] - mean);
    cov += glm::outerProduct(d, d);
  }
  glm::dvec3 axis(cov[0][0], cov[1][1], cov[2][2]);  // start near the widest coordinate axis
  axis = glm::dvec3(axis.x >= axis.y && axis.x >= axis.z ? 1 : 0, axis.y > axis.x && axis.y >= axis.z ? 1 : 0,
                    axis.z > axis.x && axis.z > axis.y ? 1 : 0) + glm::dvec3(0.1, 0.2, 0.3);
  for (int i = 0; i < 32; ++i) {
    const glm::dvec3 next = cov * axis;
    const double len = glm::length(next);
    if (len <= 0.0) break;
    axis = next / len;
  }
  return glm::normalize(glm::vec3(axis));
}

}  // namespace

float SphereObjective::outside_volume(const glm::vec3& center, float radius) const {
  if (ball.empty()) return 0.0f;
  float outside = 0.0f;
  const float inv_cell = 1.0f / grid->cell;
  for (const glm::vec3& u : ball) outside += std::clamp(grid->sample(center + radius * u) * inv_cell + 0.5f, 0.0f, 1.0f);
  const float volume = 4.0f / 3.0f * std::numbers::pi_v<float> * radius * radius * radius;
  return volume * outside / float(ball.size());
}

float SphereObjective::protrusion(const glm::vec3& center, float radius) const {
  float worst = 0.0f;
  for (const glm::vec3& d : directions) worst = std::max(worst, grid->sample(center + radius * d));
  return worst;
}

ClusterSphere fit_cluster(std::span<const glm::vec3> points, std::vector<std::uint32_t> members,
                          const SphereObjective& objective) {
  ClusterSphere sphere;
  sphere.centroid = centroid_of(points, members);
  // Start from an approximate minimum enclosing ball (Bădoiu–Clarkson: step toward the farthest
  // member with shrinking steps).
  glm::vec3 center = sphere.centroid;
  for (int i = 1; i <= 24; ++i) {
    glm::vec3 far = center;
    float far_d2 = -1.0f;
    for (std::uint32_t m : members) {
      const glm::vec3 d = points[m] - center;
      if (glm::dot(d, d) > far_d2) far_d2 = glm::dot(d, d), far = points[m];
    }
    center += (far - center) / float(i + 1);
  }
  // Minimize outside volume, plus a small share of the whole volume so that among spheres lying
  // fully inside the smaller one wins. The search measures radii on an even subset of large
  // clusters (its cost is members × evaluations); the final radius uses every member.
  std::vector<std::uint32_t> subset;
  const std::size_t stride = (members.size() + kSearchMembers - 1) / kSearchMembers;
  for (std::size_t i = 0; i < members.size(); i += std::max<std::size_t>(stride, 1)) subset.push_back(members[i]);
  auto cost = [&](const glm::vec3& c, float& radius) {
    radius = cover_radius(points, subset, c, objective);
    const float volume = 4.0f / 3.0f * std::numbers::pi_v<float> * radius * radius * radius;
    return objective.outside_volume(c, radius) + 1e-3f * volume;
  };
  float radius = 0.0f;
  float best = cost(center, radius);
  const float start_radius = std::max(radius, 1e-6f);
  float step = 0.25f * start_radius;
  static const glm::vec3 kSteps[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int evaluations = 0; step > 0.02f * start_radius && evaluations < 120;) {
    bool improved = false;
    for (const glm::vec3& s : kSteps) {
      float r = 0.0f;
      const glm::vec3 candidate = center + step * s;
      const float c = cost(candidate, r);
      ++evaluations;
      if (c < best) {
        best = c, center = candidate, radius = r, improved = true;
        break;
      }
    }
    if (!improved) step *= 0.5f;
  }
  sphere.center = center;
  sphere.radius = std::max(cover_radius(points, members, center, objective), 1e-6f);
  sphere.members = std::move(members);
  sphere.protrusion = objective.protrusion(sphere.center, sphere.radius);
  sphere.outside = objective.outside_volume(sphere.center, sphere.radius);
  return sphere;
}

BoneSphereSet::BoneSphereSet(std::span<const glm::vec3> points, std::vector<std::uint32_t> members,
                             const SphereObjective& objective)
    : points_(points), members_(std::move(members)), objective_(&objective) {
  spheres_.push_back(fit_cluster(points_, members_, *objective_));
  splittable_.push_back(members_.size() >= 2);
}

int BoneSphereSet::worst() const {
  int worst = -1;
  for (std::size_t i = 0; i < spheres_.size(); ++i)
    if (splittable_[i] && (worst < 0 || spheres_[i].protrusion > spheres_[std::size_t(worst)].protrusion)) worst = int(i);
  return worst;
}

float BoneSphereSet::worst_protrusion() const {
  float worst = 0.0f;
  for (const ClusterSphere& s : spheres_) worst = std::max(worst, s.protrusion);
  return worst;
}

float BoneSphereSet::outside_volume() const {
  float sum = 0.0f;
  for (const ClusterSphere& s : spheres_) sum += s.outside;
  return sum;
}

int BoneSphereSet::most_outside() const {
  int best = -1;
  for (std::size_t i = 0; i < spheres_.size(); ++i)
    if (splittable_[i] && (best < 0 || spheres_[i].outside > spheres_[std::size_t(best)].outside)) best = int(i);
  return best;
}

float BoneSphereSet::volume() const {
  float sum = 0.0f;
  for (const ClusterSphere& s : spheres_) sum += 4.0f / 3.0f * std::numbers::pi_v<float> * s.radius * s.radius * s.radius;
  return sum;
}

float BoneSphereSet::worst_error() const {
  const int i = worst();
  return i < 0 ? 0.0f : spheres_[std::size_t(i)].protrusion;
}

bool BoneSphereSet::split(int index, int lloyd_iterations) {
  ClusterSphere& target = spheres_[std::size_t(index)];
  const glm::vec3 axis = principal_axis(points_, target.members, target.centroid);
  std::uint32_t lo = target.members.front(), hi = lo;
  float lo_t = glm::dot(points_[lo], axis), hi_t = lo_t;
  for (std::uint32_t m : target.members) {
    const float t = glm::dot(points_[m], axis);
    if (t < lo_t) lo_t = t, lo = m;
    if (t > hi_t) hi_t = t, hi = m;
  }
  if (!(hi_t > lo_t)) {
    splittable_[std::size_t(index)] = false;
    return false;
  }
  // Two-means inside the cluster, seeded at the extremes.
  glm::vec3 seeds[2] = {points_[lo], points_[hi]};
  std::vector<std::uint32_t> halves[2];
  for (int iteration = 0; iteration < 4; ++iteration) {
    halves[0].clear(), halves[1].clear();
    for (std::uint32_t m : target.members) {
      const glm::vec3 p = points_[m];
      halves[glm::dot(p - seeds[0], p - seeds[0]) <= glm::dot(p - seeds[1], p - seeds[1]) ? 0 : 1].push_back(m);
    }
    if (halves[0].empty() || halves[1].empty()) break;
    seeds[0] = centroid_of(points_, halves[0]);
    seeds[1] = centroid_of(points_, halves[1]);
  }
  if (halves[0].empty() || halves[1].empty()) {
    splittable_[std::size_t(index)] = false;
    return false;
  }
  const std::size_t before = spheres_.size();
  spheres_[std::size_t(index)].centroid = seeds[0];
  ClusterSphere added;
  added.centroid = seeds[1];
  spheres_.push_back(std::move(added));
  splittable_.push_back(true);
  relax(std::max(lloyd_iterations, 1));
  return spheres_.size() > before;
}

void BoneSphereSet::remove(int index, int lloyd_iterations) {
  spheres_.erase(spheres_.begin() + index);
  splittable_.erase(splittable_.begin() + index);
  relax(std::max(lloyd_iterations, 1));
}

void BoneSphereSet::relax(int iterations) {
  std::vector<std::vector<std::uint32_t>> clusters(spheres_.size());
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (auto& c : clusters) c.clear();
    for (std::uint32_t m : members_) {
      const glm::vec3 p = points_[m];
      std::size_t best = 0;
      float best_d2 = glm::dot(p - spheres_[0].centroid, p - spheres_[0].centroid);
      for (std::size_t i = 1; i < spheres_.size(); ++i) {
        const float d2 = glm::dot(p - spheres_[i].centroid, p - spheres_[i].centroid);
        if (d2 < best_d2) best_d2 = d2, best = i;
      }
      clusters[best].push_back(m);
    }
    for (std::size_t i = 0; i < spheres_.size(); ++i)
      if (!clusters[i].empty()) spheres_[i].centroid = centroid_of(points_, clusters[i]);
  }
  refit(std::move(clusters));
  assign(kAssignIterations);
}

void BoneSphereSet::refit(std::vector<std::vector<std::uint32_t>> clusters) {
  std::vector<ClusterSphere> fitted;
  std::vector<bool> splittable;
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    if (clusters[i].empty()) continue;  // a sphere that lost every point disappears
    splittable.push_back(clusters[i].size() >= 2);
    fitted.push_back(fit_cluster(points_, std::move(clusters[i]), *objective_));
  }
  spheres_ = std::move(fitted);
  splittable_ = std::move(splittable);
}

void BoneSphereSet::assign(int iterations) {
  if (spheres_.size() < 2) return;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::vector<std::vector<std::uint32_t>> clusters(spheres_.size());
    bool moved = false;
    for (std::size_t i = 0; i < spheres_.size(); ++i)
      for (std::uint32_t m : spheres_[i].members) {
        const glm::vec3 p = points_[m];
        std::size_t best = i;
        float best_gap = glm::length(p - spheres_[i].center) - spheres_[i].radius;
        for (std::size_t j = 0; j < spheres_.size(); ++j) {
          const float gap = glm::length(p - spheres_[j].center) - spheres_[j].radius;
          if (gap < best_gap) best_gap = gap, best = j;
        }
        moved = moved || best != i;
        clusters[best].push_back(m);
      }
    if (!moved) return;
    for (auto& c : clusters) std::sort(c.begin(), c.end());  // member order independent of the pass
    const std::vector<ClusterSphere> before = spheres_;
    const std::vector<bool> before_splittable = splittable_;
    const float outside = outside_volume(), worst = worst_protrusion();
    refit(std::move(clusters));
    if (!(outside_volume() < outside) || worst_protrusion() > std::max(worst, objective_->tolerance)) {
      spheres_ = before;
      splittable_ = before_splittable;
      return;
    }
  }
}

}  // namespace proxygi::proxies
