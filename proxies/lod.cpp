#include "proxies/lod.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "proxies/culling.h"

namespace proxygi::proxies {
namespace {

struct Cluster {
  std::vector<int> children;  // finer-level sphere indices
  std::vector<int> members;   // rig sphere indices
  int group = 0;
  WorldSphere sphere;         // in the reference pose
};

float cube(float r) { return r * r * r; }

WorldSphere bound_children(const std::vector<WorldSphere>& finer, const std::vector<int>& children) {
  if (children.size() == 1) return finer[std::size_t(children.front())];
  std::vector<WorldSphere> picked;
  picked.reserve(children.size());
  for (int c : children) picked.push_back(finer[std::size_t(c)]);
  return bounding_sphere(picked);
}

template <class T>
std::vector<T> merged(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> out;
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace

std::vector<int> LodLevels::counts() const {
  std::vector<int> out;
  for (const LodLevel& level : levels) out.push_back(int(level.spheres.size()));
  return out;
}

Status BuildLodLevelsJob::validate() const {
  if (levels == nullptr) return make_error("lod levels: output is null");
  if (groups.size() != spheres.size() || nodes.size() != spheres.size())
    return make_error("lod levels: " + std::to_string(spheres.size()) + " spheres but " + std::to_string(groups.size()) +
                      " groups and " + std::to_string(nodes.size()) + " nodes");
  if (min_spheres < 1) return make_error("lod levels: min_spheres must be >= 1 (got " + std::to_string(min_spheres) + ")");
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const WorldSphere& s = spheres[i];
    if (!std::isfinite(s.center.x) || !std::isfinite(s.center.y) || !std::isfinite(s.center.z) || !(s.radius > 0.0f) ||
        !std::isfinite(s.radius))
      return make_error("lod levels: sphere " + std::to_string(i) + " is not finite with radius > 0");
  }
  return {};
}

Status BuildLodLevelsJob::run() const {
  if (Status s = validate(); !s) return s;
  LodLevels& out = *levels;
  out.levels.clear();
  LodLevel rig;
  std::vector<WorldSphere> finer(spheres.begin(), spheres.end());
  std::vector<int> finer_groups(groups.begin(), groups.end());
  for (std::size_t i = 0; i < spheres.size(); ++i) rig.spheres.push_back({{int(i)}, {}, nodes[i], -1});
  out.levels.push_back(std::move(rig));
  while (int(finer.size()) > min_spheres) {
    const int target = std::max(min_spheres, int(finer.size() + 1) / 2);
    std::vector<Cluster> clusters;
    for (std::size_t i = 0; i < finer.size(); ++i)
      clusters.push_back({{int(i)}, out.levels.back().spheres[i].members, finer_groups[i], finer[i]});
    while (int(clusters.size()) > target) {
      // The pair whose bounding sphere adds the least volume, within one chain while any chain
      // still holds two clusters.
      std::size_t best_a = 0, best_b = 1;
      bool best_cross = true;
      float best_growth = std::numeric_limits<float>::infinity();
      WorldSphere best_sphere;
      for (std::size_t a = 0; a < clusters.size(); ++a)
        for (std::size_t b = a + 1; b < clusters.size(); ++b) {
          const bool cross = clusters[a].group != clusters[b].group;
          if (cross && !best_cross) continue;
          const WorldSphere sphere = bound_children(finer, merged(clusters[a].children, clusters[b].children));
          const float growth = cube(sphere.radius) - cube(clusters[a].sphere.radius) - cube(clusters[b].sphere.radius);
          if ((best_cross && !cross) || growth < best_growth) {
            best_a = a, best_b = b, best_cross = cross, best_growth = growth, best_sphere = sphere;
          }
        }
      Cluster& kept = clusters[best_a];
      const Cluster& gone = clusters[best_b];
      if (gone.sphere.radius > kept.sphere.radius) kept.group = gone.group;
      kept.children = merged(kept.children, gone.children);
      kept.members = merged(kept.members, gone.members);
      kept.sphere = best_sphere;
      clusters.erase(clusters.begin() + std::ptrdiff_t(best_b));
    }
    // Order the level by first member so it reads like the rig.
    std::sort(clusters.begin(), clusters.end(), [](const Cluster& x, const Cluster& y) { return x.members[0] < y.members[0]; });
    LodLevel level;
    std::vector<WorldSphere> coarse;
    std::vector<int> coarse_groups;
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      LodSphere sphere{clusters[c].members, clusters[c].children, -1, -1};
      int largest = clusters[c].members.front();
      for (int m : clusters[c].members)
        if (spheres[std::size_t(m)].radius > spheres[std::size_t(largest)].radius) largest = m;
      sphere.node = nodes[std::size_t(largest)];
      for (int child : clusters[c].children) out.levels.back().spheres[std::size_t(child)].coarser = int(c);
      level.spheres.push_back(std::move(sphere));
      coarse.push_back(clusters[c].sphere);
      coarse_groups.push_back(clusters[c].group);
    }
    out.levels.push_back(std::move(level));
    finer = std::move(coarse);
    finer_groups = std::move(coarse_groups);
  }
  return {};
}

void evaluate_lod_levels(const LodLevels& levels, int last, std::span<const WorldSphere> tracked,
                         std::vector<std::vector<WorldSphere>>& out) {
  last = std::clamp(last, 0, int(levels.levels.size()) - 1);
  out.resize(std::size_t(last + 1));
  out[0].assign(tracked.begin(), tracked.end());
  for (int k = 1; k <= last; ++k) {
    const LodLevel& level = levels.levels[std::size_t(k)];
    out[std::size_t(k)].resize(level.spheres.size());
    for (std::size_t i = 0; i < level.spheres.size(); ++i)
      out[std::size_t(k)][i] = bound_children(out[std::size_t(k - 1)], level.spheres[i].children);
  }
}

Status validate_lod_levels(const LodLevels& levels, std::span<const WorldSphere> spheres, float tolerance) {
  if (levels.levels.empty()) return make_error("lod levels: no level");
  const LodLevel& rig = levels.levels.front();
  if (rig.spheres.size() != spheres.size())
    return make_error("lod levels: level 0 holds " + std::to_string(rig.spheres.size()) + " spheres, the rig " +
                      std::to_string(spheres.size()));
  for (std::size_t i = 0; i < rig.spheres.size(); ++i)
    if (rig.spheres[i].members != std::vector<int>{int(i)} || !rig.spheres[i].children.empty())
      return make_error("lod levels: level 0 sphere " + std::to_string(i) + " is not rig sphere " + std::to_string(i));
  std::vector<std::vector<WorldSphere>> evaluated;
  evaluate_lod_levels(levels, int(levels.levels.size()) - 1, spheres, evaluated);
  for (std::size_t k = 0; k < levels.levels.size(); ++k) {
    const LodLevel& level = levels.levels[k];
    const std::string name = "lod levels: level " + std::to_string(k);
    std::vector<int> owner(spheres.size(), -1);
    for (std::size_t i = 0; i < level.spheres.size(); ++i) {
      const LodSphere& sphere = level.spheres[i];
      const std::string where = name + " sphere " + std::to_string(i);
      if (sphere.members.empty()) return make_error(where + ": no member");
      for (int m : sphere.members) {
        if (m < 0 || std::size_t(m) >= spheres.size()) return make_error(where + ": member " + std::to_string(m) + " out of range");
        if (owner[std::size_t(m)] >= 0)
          return make_error(where + ": rig sphere " + std::to_string(m) + " also in sphere " + std::to_string(owner[std::size_t(m)]));
        owner[std::size_t(m)] = int(i);
      }
      const bool coarsest = k + 1 == levels.levels.size();
      if (coarsest ? sphere.coarser != -1
                   : sphere.coarser < 0 || std::size_t(sphere.coarser) >= levels.levels[k + 1].spheres.size())
        return make_error(where + ": coarser " + std::to_string(sphere.coarser) + " is not a sphere of the next level");
      if (k == 0) continue;
      const LodLevel& finer = levels.levels[k - 1];
      if (finer.spheres.size() <= level.spheres.size())
        return make_error(name + ": " + std::to_string(level.spheres.size()) + " spheres, not fewer than level " +
                          std::to_string(k - 1) + "'s " + std::to_string(finer.spheres.size()));
      std::vector<int> united;
      if (sphere.children.empty()) return make_error(where + ": no child");
      for (int c : sphere.children) {
        if (c < 0 || std::size_t(c) >= finer.spheres.size() || finer.spheres[std::size_t(c)].coarser != int(i))
          return make_error(where + ": child " + std::to_string(c) + " does not name it as its coarser sphere");
        united = merged(united, finer.spheres[std::size_t(c)].members);
        const WorldSphere& inner = evaluated[k - 1][std::size_t(c)];
        const WorldSphere& outer = evaluated[k][i];
        const float reach = glm::length(inner.center - outer.center) + inner.radius;
        if (!(reach <= outer.radius + tolerance))
          return make_error(where + ": does not cover child " + std::to_string(c) + " (reaches " + std::to_string(reach) +
                            " m, radius " + std::to_string(outer.radius) + " m)");
      }
      if (united != sphere.members) return make_error(where + ": members are not the union of its children's");
    }
    for (std::size_t m = 0; m < owner.size(); ++m)
      if (owner[m] < 0) return make_error(name + ": rig sphere " + std::to_string(m) + " in no sphere");
  }
  return {};
}

int LodChooser::level_for(float radius_px) const {
  const float wanted = radius_px / pixels_per_sphere;
  for (int k = int(counts.size()) - 1; k > 0; --k)
    if (float(counts[std::size_t(k)]) >= wanted) return k;
  return 0;
}

LodChoice LodChooser::step(const LodChoice& choice, float radius_px) const {
  LodChoice next = choice;
  if (choice.from != choice.to) {
    if (++next.frames_into_fade >= fade_frames) next = {choice.to, choice.to, 0};
    return next;
  }
  const int wanted = level_for(radius_px);
  const bool leaves = wanted < choice.to ? level_for(radius_px * (1.0f - hysteresis)) < choice.to
                                         : wanted > choice.to && level_for(radius_px * (1.0f + hysteresis)) > choice.to;
  if (!leaves) return next;
  if (fade_frames <= 1) return {wanted, wanted, 0};
  return {choice.to, wanted, 1};
}

float LodChooser::fade(const LodChoice& choice) const {
  if (choice.from == choice.to) return 1.0f;
  return float(choice.frames_into_fade) / float(fade_frames);
}

void append_lod_spheres(const LodLevels& levels, const LodChoice& choice, float fade,
                        std::span<const WorldSphere> tracked, std::vector<std::vector<WorldSphere>>& scratch,
                        std::vector<WeightedSphere>& out) {
  evaluate_lod_levels(levels, std::max(choice.from, choice.to), tracked, scratch);
  const auto& from_level = levels.levels[std::size_t(choice.from)].spheres;
  const auto& to_level = levels.levels[std::size_t(choice.to)].spheres;
  if (choice.from == choice.to || fade >= 1.0f) {
    for (const WorldSphere& s : scratch[std::size_t(choice.to)]) out.push_back({s, 1.0f});
    return;
  }
  // Shared spheres (same members in both levels, so the same evaluated sphere) go once, weight 1.
  auto shared_in = [](const std::vector<LodSphere>& level, const std::vector<int>& members) {
    for (std::size_t i = 0; i < level.size(); ++i)
      if (level[i].members.front() == members.front()) return level[i].members == members ? int(i) : -1;
    return -1;
  };
  for (std::size_t i = 0; i < from_level.size(); ++i) {
    const bool shared = shared_in(to_level, from_level[i].members) >= 0;
    const float weight = shared ? 1.0f : 1.0f - fade;
    if (weight > 0.0f) out.push_back({scratch[std::size_t(choice.from)][i], weight});
  }
  if (fade <= 0.0f) return;
  for (std::size_t i = 0; i < to_level.size(); ++i)
    if (shared_in(from_level, to_level[i].members) < 0) out.push_back({scratch[std::size_t(choice.to)][i], fade});
}

float projected_radius_pixels(const glm::vec3& center, float radius, const glm::vec3& eye, float focal_pixels) {
  const float distance = std::max(glm::length(center - eye), radius);
  return distance > 0.0f ? radius * focal_pixels / distance : 0.0f;
}

}  // namespace proxygi::proxies
