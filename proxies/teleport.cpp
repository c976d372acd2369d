#include "proxies/teleport.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace proxygi::proxies {
namespace {

constexpr float kNone = std::numeric_limits<float>::infinity();

float total_outside(std::span<const std::unique_ptr<BoneSphereSet>> sets) {
  float sum = 0.0f;
  for (const auto& set : sets) sum += set->outside_volume();
  return sum;
}

// The cheapest removal from one set: the set without it and what that adds to its outside volume.
struct Removal {
  float cost = kNone;  // m³; kNone when no removal keeps the protrusion bound
  std::unique_ptr<BoneSphereSet> result;
};

Removal cheapest_removal(const BoneSphereSet& base, float allowed, int lloyd) {
  Removal best;
  if (base.spheres().size() < 2) return best;
  for (std::size_t j = 0; j < base.spheres().size(); ++j) {
    auto candidate = std::make_unique<BoneSphereSet>(base);
    candidate->remove(int(j), lloyd);
    if (candidate->worst_protrusion() > allowed) continue;
    const float cost = candidate->outside_volume() - base.outside_volume();
    if (cost < best.cost) best.cost = cost, best.result = std::move(candidate);
  }
  return best;
}

struct Candidate {
  float outside;
  int set, sphere;
};

// The `count` spheres with the largest outside volume, over the sets that can still split.
std::vector<Candidate> split_candidates(std::span<const std::unique_ptr<BoneSphereSet>> sets, int count) {
  std::vector<Candidate> all;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (sets[i]->worst() < 0) continue;
    for (std::size_t j = 0; j < sets[i]->spheres().size(); ++j)
      if (sets[i]->spheres()[j].outside > 0.0f) all.push_back({sets[i]->spheres()[j].outside, int(i), int(j)});
  }
  std::stable_sort(all.begin(), all.end(), [](const Candidate& a, const Candidate& b) { return a.outside > b.outside; });
  if (all.size() > std::size_t(count)) all.resize(std::size_t(count));
  return all;
}

}  // namespace

Status TeleportJob::validate() const {
  for (const auto& set : sets)
    if (!set) return make_error("teleport: a sphere set is null");
  if (!(tolerance > 0.0f) || !std::isfinite(tolerance)) return make_error("teleport: tolerance must be a finite number > 0");
  if (rounds < 0 || candidates < 1 || worsening < 0 || lloyd_iterations < 1)
    return make_error("teleport: rounds >= 0, candidates >= 1, worsening >= 0 and lloyd_iterations >= 1 required");
  return {};
}

Status TeleportJob::run() const {
  if (Status s = validate(); !s) return s;
  TeleportStats local;
  TeleportStats& out = stats ? *stats : local;
  out = TeleportStats{};
  out.outside_before = out.outside_after = total_outside(sets);
  float allowed = kNone;

  // Each set's cheapest removal, recomputed only for the sets a move changed.
  std::vector<Removal> removals(sets.size());
  std::vector<bool> stale(sets.size(), true);
  std::vector<BoneSphereSet> best_state;
  float best_total = out.outside_before;
  if (worsening > 0)  // the best state seen; a worsening move may be undone at the end
    for (const auto& set : sets) best_state.push_back(*set);
  int streak = 0;
  for (int round = 0; round < rounds; ++round) {
    // The bound (header: never above the worst before the teleport) is retaken before each move,
    // as tight as the moves made it; when it tightens, every cached removal is stale.
    float worst = 0.0f;
    for (const auto& set : sets) worst = std::max(worst, set->worst_protrusion());
    if (std::max(tolerance, worst) != allowed) allowed = std::max(tolerance, worst), stale.assign(sets.size(), true);
    for (std::size_t i = 0; i < sets.size(); ++i)
      if (stale[i]) removals[i] = cheapest_removal(*sets[i], allowed, lloyd_iterations), stale[i] = false;

    float best_net = kNone;
    int move_split = -1, move_remove = -1;
    std::unique_ptr<BoneSphereSet> move_split_result, move_remove_result;
    for (const Candidate& c : split_candidates(sets, candidates)) {
      const BoneSphereSet& base = *sets[std::size_t(c.set)];
      auto split = std::make_unique<BoneSphereSet>(base);
      if (!split->split(c.sphere, lloyd_iterations) || split->worst_protrusion() > allowed) continue;
      const float gain = base.outside_volume() - split->outside_volume();
      if (!(gain > 0.0f)) continue;
      // The removal over every set in order; the split set is taken as split.
      Removal own = cheapest_removal(*split, allowed, lloyd_iterations);
      float cost = kNone;
      int remove_set = -1;
      for (std::size_t i = 0; i < sets.size(); ++i) {
        const float ci = int(i) == c.set ? own.cost : removals[i].cost;
        if (ci < cost) cost = ci, remove_set = int(i);
      }
      if (remove_set < 0 || !(cost - gain < best_net)) continue;
      best_net = cost - gain;
      move_split = c.set, move_remove = remove_set;
      move_remove_result = remove_set == c.set ? std::move(own.result) : nullptr;
      move_split_result = std::move(split);
    }
    if (move_split < 0) break;
    if (!(best_net < 0.0f) && streak >= worsening) break;
    // Make the move.
    if (move_remove == move_split) {
      *sets[std::size_t(move_split)] = std::move(*move_remove_result);
    } else {
      *sets[std::size_t(move_split)] = std::move(*move_split_result);
      *sets[std::size_t(move_remove)] = std::move(*removals[std::size_t(move_remove)].result);
    }
    stale[std::size_t(move_split)] = stale[std::size_t(move_remove)] = true;
    ++out.moves;
    streak = best_net < 0.0f ? 0 : streak + 1;
    const float total = total_outside(sets);
    if (total < best_total) {
      best_total = total, out.kept = out.moves;
      if (worsening > 0) {
        best_state.clear();
        for (const auto& set : sets) best_state.push_back(*set);
      }
    }
  }
  if (out.kept < out.moves && worsening > 0)
    for (std::size_t i = 0; i < sets.size(); ++i) *sets[i] = best_state[i];
  out.outside_after = total_outside(sets);
  return {};
}

}  // namespace proxygi::proxies
