#include "proxies/proxy_rig.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <numbers>

namespace proxygi::proxies {

const char* binding_name(Binding binding) { return binding == Binding::rigid ? "rigid" : "blended"; }

RigSummary summarize_rig(const ProxyRig& rig) {
  RigSummary summary;
  summary.sphere_count = int(rig.spheres.size());
  std::vector<int> nodes;  // node of each spheres_per_bone entry
  std::map<std::string, std::set<int>> nodes_by_name;
  for (const ProxySphere& s : rig.spheres) nodes_by_name[s.bone].insert(s.node);
  for (const ProxySphere& s : rig.spheres) {
    const auto it = std::find(nodes.begin(), nodes.end(), s.node);
    if (it == nodes.end()) {
      const bool ambiguous = s.bone.empty() || nodes_by_name[s.bone].size() > 1;
      summary.spheres_per_bone.emplace_back(ambiguous ? s.bone + "#" + std::to_string(s.node) : s.bone, 1);
      nodes.push_back(s.node);
    } else {
      ++summary.spheres_per_bone[std::size_t(it - nodes.begin())].second;
    }
    summary.min_radius = &s == &rig.spheres.front() ? s.radius : std::min(summary.min_radius, s.radius);
    summary.max_radius = std::max(summary.max_radius, s.radius);
    summary.total_volume += 4.0f / 3.0f * std::numbers::pi_v<float> * s.radius * s.radius * s.radius;
  }
  summary.bone_count = int(summary.spheres_per_bone.size());
  return summary;
}

std::string format_rig_summary(const ProxyRig& rig) {
  const RigSummary s = summarize_rig(rig);
  char line[512];
  std::string out;
  std::snprintf(line, sizeof line, "proxies: %d spheres on %d bones, radius %.4g..%.4g m, binding %s, tolerance %.3g (x %.4g m diagonal)\n",
                s.sphere_count, s.bone_count, double(s.min_radius), double(s.max_radius), binding_name(rig.binding),
                double(rig.tolerance), double(rig.diagonal));
  out += line;
  if (rig.has_quality) {
    std::snprintf(line, sizeof line,
                  "  quality: coverage %.2f%%, outside volume %.1f%%, hausdorff surface->spheres %.4g m, spheres->surface %.4g m\n",
                  100.0 * double(rig.quality.coverage), 100.0 * double(rig.quality.outside_volume_ratio),
                  double(rig.quality.hausdorff_surface_to_spheres), double(rig.quality.hausdorff_spheres_to_surface));
    out += line;
  }
  out += "  per bone:";
  for (const auto& [bone, count] : s.spheres_per_bone) out += " " + bone + "=" + std::to_string(count);
  out += "\n";
  return out;
}

}  // namespace proxygi::proxies
