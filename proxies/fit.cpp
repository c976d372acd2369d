#include "proxies/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <Eigen/Eigenvalues>

#include "proxies/sphere_set_fit.h"
#include "proxies/teleport.h"

namespace proxygi::proxies {
namespace {

float max_axis_scale(const glm::mat4& m) {
  return std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

// A bone region thinner than this fraction of its width counts as flat.
constexpr float kFlatRatio = 0.25f;

std::string bone_label(const anim::Character& character, int node) {
  return "bone '" + character.nodes[std::size_t(node)].name + "' (node " + std::to_string(node) + ")";
}

// Extents of a point set along its principal axes, smallest first, meters.
glm::vec3 principal_extents(std::span<const glm::vec3> points, const std::vector<std::uint32_t>& members) {
  if (members.size() < 3) return glm::vec3(0.0f);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::uint32_t m : members) mean += Eigen::Vector3d(points[m].x, points[m].y, points[m].z);
  mean /= double(members.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::uint32_t m : members) {
    const Eigen::Vector3d d = Eigen::Vector3d(points[m].x, points[m].y, points[m].z) - mean;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);  // eigenvalues ascending
  glm::vec3 extents(0.0f);
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d direction = solver.eigenvectors().col(axis);
    double lo = 1e30, hi = -1e30;
    for (std::uint32_t m : members) {
      const double t = direction.dot(Eigen::Vector3d(points[m].x, points[m].y, points[m].z));
      lo = std::min(lo, t), hi = std::max(hi, t);
    }
    extents[axis] = float(hi - lo);
  }
  return extents;
}

}  // namespace

Status FitProxiesJob::validate() const {
  if (character == nullptr) return make_error("fit: character is null");
  if (result == nullptr) return make_error("fit: result is null");
  if (!(options.tolerance > 0.0f) || !std::isfinite(options.tolerance))
    return make_error("fit: tolerance must be a finite number > 0");
  if (options.max_spheres < 1) return make_error("fit: max_spheres must be >= 1");
  if (options.surface_samples < 1 || options.interior_samples < 0 || options.grid_resolution < 8 ||
      options.lloyd_iterations < 1)
    return make_error("fit: sample counts, grid resolution (>= 8) or Lloyd iterations out of range");
  if (!(options.surface_slack >= 0.0f && options.surface_slack < 1.0f) || options.teleport_rounds < 0 ||
      options.teleport_candidates < 1 || options.teleport_worsening < 0)
    return make_error("fit: surface_slack must be in [0, 1), teleport_rounds >= 0, teleport_candidates >= 1 and "
                      "teleport_worsening >= 0");
  return {};
}

Status FitProxiesJob::run() const {
  if (Status s = validate(); !s) return s;
  const auto start = std::chrono::steady_clock::now();
  const anim::Character& ch = *character;
  FitResult& out = *result;
  out = FitResult{};

  Result<BindSurface> surface = extract_bind_surface(ch);
  if (!surface) return surface.error();
  out.surface = std::move(surface.value());
  const BindSurface& bind = out.surface;
  const Box box = bounds_of(bind.soup.positions);
  out.diagonal = std::max(box.diagonal(), 1e-6f);
  out.tolerance_m = options.tolerance * out.diagonal;
  const float tau = out.tolerance_m;

  // Distance grid: fixed resolution relative to the character, band wide enough to measure
  // protrusions a little past the tolerance.
  const float cell = out.diagonal / float(options.grid_resolution);
  const float band = 1.5f * tau + 2.0f * cell;
  WindingIndex winding;
  winding.build(bind.soup, 64);
  const DistanceGrid grid = build_distance_grid(bind.soup, winding, box, cell, band);

  // Points: vertices, surface samples, interior points (in that order).
  out.samples = sample_surface(ch, bind, options.surface_samples, options.seed);
  std::vector<glm::vec3> points(bind.soup.positions);
  std::vector<int> point_bone;
  point_bone.reserve(points.size() + out.samples.size());
  for (const Influences& inf : bind.influences) point_bone.push_back(inf.dominant());
  const std::uint32_t first_sample = std::uint32_t(points.size());
  for (SurfaceSample& s : out.samples) {
    // A sample joins a bone that owns vertices (interpolated weights can favour a bone that
    // dominates no vertex); otherwise the bone of its nearest corner.
    if (s.bone < 0 || bind.vertex_count_per_bone[std::size_t(s.bone)] == 0) {
      const glm::uvec3& tri = bind.soup.triangles[s.triangle];
      const int corner = s.barycentric.x >= s.barycentric.y && s.barycentric.x >= s.barycentric.z ? 0
                         : s.barycentric.y >= s.barycentric.z                                   ? 1 : 2;
      s.bone = bind.influences[tri[corner]].dominant();
    }
    points.push_back(s.position);
    point_bone.push_back(s.bone);
  }
  std::vector<glm::vec3> sample_positions;
  for (const SurfaceSample& s : out.samples) sample_positions.push_back(s.position);
  NearestPointGrid nearest;
  nearest.build(sample_positions, 2.0f * cell);
  const std::uint32_t first_interior = std::uint32_t(points.size());
  for (const glm::vec3& p : sample_interior(grid, options.interior_samples, options.seed + 1)) {
    const int n = nearest.nearest(p);
    if (n < 0) break;
    points.push_back(p);
    point_bone.push_back(out.samples[std::size_t(n)].bone);
  }

  // Members per bone.
  std::vector<std::vector<std::uint32_t>> members(ch.nodes.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) members[std::size_t(point_bone[i])].push_back(i);

  const std::vector<glm::vec3> ball = unit_ball_points(96);
  const std::vector<glm::vec3> directions = fibonacci_directions(128);
  const SphereObjective objective{&grid, ball, directions, options.surface_slack * tau, tau};

  std::vector<int> bones;
  std::vector<std::unique_ptr<BoneSphereSet>> sets;
  std::vector<bool> tighten;  // not warned flat or open: the outside-volume splits may work on it
  for (std::size_t bone = 0; bone < members.size(); ++bone) {
    if (members[bone].empty()) continue;
    // Warnings for regions spheres can only over-cover.
    std::vector<std::uint32_t> surface_members;
    int interior = 0;
    for (std::uint32_t m : members[bone]) (m < first_interior ? surface_members.push_back(m) : void(++interior));
    // Flat: much thinner than it is wide (a plate, an ear, a cape), and wide enough that the
    // tolerance cannot absorb it. Long thin parts (fingers) are fine for spheres.
    const glm::vec3 extents = principal_extents(points, surface_members);
    char line[256];
    if (interior == 0) {
      std::snprintf(line, sizeof line, ": no interior volume (open or flat surface, thickness %.4g m): spheres over-cover it",
                    double(extents[0]));
      out.rig.warnings.push_back(bone_label(ch, int(bone)) + line);
      tighten.push_back(false);
    } else if (extents[0] < kFlatRatio * extents[1] && extents[1] > tau) {
      std::snprintf(line, sizeof line, ": thin or flat region (%.4g m thick, %.4g m wide): spheres over-cover it",
                    double(extents[0]), double(extents[1]));
      out.rig.warnings.push_back(bone_label(ch, int(bone)) + line);
      tighten.push_back(false);
    } else {
      tighten.push_back(true);
    }
    bones.push_back(int(bone));
    sets.push_back(std::make_unique<BoneSphereSet>(points, members[bone], objective));
  }

  // Greedy refinement. First the globally worst protrusion above the tolerance; then, while the
  // spheres of bones that are neither flat nor open (spheres can only over-cover those) have
  // more than outside_target of their volume outside the mesh, the one with the largest outside
  // volume. A failed split, or an outside split that does not lower its bone's outside volume,
  // counts against the bone (three and it is left alone).
  auto count = [&] {
    std::size_t total = 0;
    for (const auto& set : sets) total += set->spheres().size();
    return total;
  };
  std::vector<int> failures(sets.size(), 0), outside_failures(sets.size(), 0);
  for (int guard = 0; count() < std::size_t(options.max_spheres) && guard < 8 * options.max_spheres; ++guard) {
    int worst_set = -1;
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (failures[i] < 3 && (worst_set < 0 || sets[i]->worst_error() > sets[std::size_t(worst_set)]->worst_error()))
        worst_set = int(i);
    if (worst_set >= 0 && sets[std::size_t(worst_set)]->worst_error() > tau) {
      BoneSphereSet& set = *sets[std::size_t(worst_set)];
      const int worst = set.worst();
      if (worst < 0 || !set.split(worst, options.lloyd_iterations)) ++failures[std::size_t(worst_set)];
      continue;
    }
    float outside = 0.0f, volume = 0.0f;
    int best_set = -1, best_sphere = -1;
    for (std::size_t i = 0; i < sets.size(); ++i) {
      if (!tighten[i]) continue;
      outside += sets[i]->outside_volume(), volume += sets[i]->volume();
      const int j = sets[i]->most_outside();
      if (outside_failures[i] < 3 && j >= 0 &&
          (best_set < 0 || sets[i]->spheres()[std::size_t(j)].outside > sets[std::size_t(best_set)]->spheres()[std::size_t(best_sphere)].outside))
        best_set = int(i), best_sphere = j;
    }
    if (best_set < 0 || !(outside > options.outside_target * volume)) break;
    BoneSphereSet& set = *sets[std::size_t(best_set)];
    const float before = set.outside_volume();
    if (!set.split(best_sphere, options.lloyd_iterations) || !(set.outside_volume() < before)) ++outside_failures[std::size_t(best_set)];
  }
  TeleportJob teleport;
  teleport.sets = sets;
  teleport.tolerance = tau;
  teleport.rounds = options.teleport_rounds;
  teleport.candidates = options.teleport_candidates;
  teleport.worsening = options.teleport_worsening;
  teleport.lloyd_iterations = options.lloyd_iterations;
  teleport.stats = &out.teleport;
  if (Status s = teleport.run(); !s) return s;

  // Rig spheres in bone space, with albedo and mean weights from what each sphere stands for.
  out.rig.tolerance = options.tolerance;
  out.rig.max_spheres = options.max_spheres;
  out.rig.fit_version = kFitVersion;
  out.rig.diagonal = out.diagonal;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const int bone = bones[i];
    glm::dvec3 bone_albedo(0.0);
    std::size_t bone_albedo_count = 0;
    for (const ClusterSphere& cluster : sets[i]->spheres())
      for (std::uint32_t m : cluster.members)
        if (m >= first_sample && m < first_interior) bone_albedo += glm::dvec3(out.samples[m - first_sample].albedo), ++bone_albedo_count;
    for (const ClusterSphere& cluster : sets[i]->spheres()) {
      FittedSphere fitted;
      fitted.bone = bone;
      fitted.center = cluster.center;
      fitted.radius = cluster.radius;
      fitted.protrusion = cluster.protrusion;
      glm::dvec3 albedo(0.0);
      std::vector<std::pair<int, float>> weight_sum;
      for (std::uint32_t m : cluster.members) {
        if (m < first_sample) {
          const Influences& inf = bind.influences[m];
          for (int k = 0; k < kMaxInfluences; ++k) accumulate(weight_sum, inf.nodes[std::size_t(k)], inf.weights[std::size_t(k)]);
        } else if (m < first_interior) {
          const SurfaceSample& s = out.samples[m - first_sample];
          fitted.samples.push_back(m - first_sample);
          albedo += glm::dvec3(s.albedo);
          const Influences inf = sample_influences(bind, s);
          for (int k = 0; k < kMaxInfluences; ++k) accumulate(weight_sum, inf.nodes[std::size_t(k)], inf.weights[std::size_t(k)]);
        }
      }
      ProxySphere sphere;
      sphere.node = bone;
      sphere.bone = ch.nodes[std::size_t(bone)].name;
      const glm::mat4& to_bone = bind.bind_to_bone[std::size_t(bone)];
      sphere.center = glm::vec3(to_bone * glm::vec4(cluster.center, 1.0f));
      sphere.radius = cluster.radius * max_axis_scale(to_bone);
      sphere.albedo = !fitted.samples.empty() ? glm::vec3(albedo / double(fitted.samples.size()))
                      : bone_albedo_count > 0 ? glm::vec3(bone_albedo / double(bone_albedo_count))
                                              : glm::vec3(1.0f);
      const Influences mean = to_influences(weight_sum);
      float total = 0.0f;
      for (int k = 0; k < kSphereWeights; ++k) total += mean.weights[std::size_t(k)];
      for (int k = 0; k < kSphereWeights && mean.nodes[std::size_t(k)] >= 0; ++k) {
        sphere.weight_nodes[std::size_t(k)] = mean.nodes[std::size_t(k)];
        sphere.weights[std::size_t(k)] = mean.weights[std::size_t(k)] / total;
      }
      out.rig.spheres.push_back(sphere);
      out.fitted.push_back(std::move(fitted));
    }
  }
  for (const std::string& w : bind.warnings) out.rig.warnings.push_back(w);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.rig.fit_seconds = out.seconds;
  return {};
}

}  // namespace proxygi::proxies
