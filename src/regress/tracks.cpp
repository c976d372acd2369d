#include "regress/tracks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <nlohmann/json.hpp>

namespace proxygi::regress {
namespace {

using nlohmann::json;

double rotation_displacement(const glm::dmat4& a, const glm::dmat4& b, double distance) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, glm::length(glm::dvec3(a[c]) - glm::dvec3(b[c])));
  return worst * distance;
}

std::string format(const char* pattern, const std::string& what, int frame, double mm, double tolerance) {
  char line[256];
  std::snprintf(line, sizeof(line), pattern, what.c_str(), frame, mm, tolerance);
  return line;
}

}  // namespace

Result<Tracks> compute_tracks(const ScenarioRun& run, const Check& check) {
  Tracks tracks;
  world::WorldState state;
  for (int frame : check.frames) {
    if (Status s = run.evaluate(frame, state); !s) return s.error();
    FrameTrack out{frame, {}};
    for (std::size_t i = 0; i < run.world().instances().size(); ++i) {
      const anim::Character& character = run.world().instances()[i].model->character;
      const anim::PoseBuffers& pose = state.instances[i].pose;
      InstanceTrack track;
      if (check.joints) {
        std::vector<int> nodes;
        for (const anim::Skin& skin : character.skins) nodes.insert(nodes.end(), skin.joints.begin(), skin.joints.end());
        if (nodes.empty())
          for (std::size_t n = 0; n < character.nodes.size(); ++n) nodes.push_back(int(n));
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        for (int node : nodes) {
          track.joint_names.push_back(character.nodes[std::size_t(node)].name);
          track.joints.push_back(glm::dmat4(pose.world[std::size_t(node)]));
        }
      }
      if (check.vertices > 0) {
        auto meshes = run.world().pose_instance(state, i);
        if (!meshes) return meshes.error();
        std::vector<const glm::vec3*> all;
        for (const auto& primitive : *meshes)
          for (const auto& p : primitive.positions) all.push_back(&p);
        std::mt19937 random(check.seed + std::uint32_t(i));  // raw engine output: the same on every platform
        for (int k = 0; k < check.vertices && !all.empty(); ++k) track.vertices.push_back(glm::dvec3(*all[random() % all.size()]));
      }
      if (check.proxies)
        for (const auto& sphere : state.instances[i].spheres) track.proxies.push_back(glm::dvec4(glm::dvec3(sphere.center), sphere.radius));
      out.instances.push_back(std::move(track));
    }
    tracks.push_back(std::move(out));
  }
  return tracks;
}

std::string tracks_to_json(const Tracks& tracks) {
  json j = json::array();
  for (const FrameTrack& frame : tracks) {
    json f = {{"frame", frame.frame}, {"instances", json::array()}};
    for (const InstanceTrack& t : frame.instances) {
      json joints = json::array(), vertices = json::array(), proxies = json::array();
      for (std::size_t k = 0; k < t.joints.size(); ++k) {
        json m = json::array();
        for (int c = 0; c < 4; ++c)
          for (int r = 0; r < 4; ++r) m.push_back(t.joints[k][c][r]);
        joints.push_back({{"name", t.joint_names[k]}, {"m", m}});
      }
      for (const auto& v : t.vertices) vertices.push_back({v.x, v.y, v.z});
      for (const auto& p : t.proxies) proxies.push_back({p.x, p.y, p.z, p.w});
      f["instances"].push_back({{"joints", joints}, {"vertices", vertices}, {"proxies", proxies}});
    }
    j.push_back(f);
  }
  return j.dump() + "\n";  // nlohmann writes doubles round-trip exactly
}

Result<Tracks> tracks_from_json(const std::string& text, const std::string& where) {
  try {
    Tracks tracks;
    for (const json& f : json::parse(text)) {
      FrameTrack frame{f.at("frame").get<int>(), {}};
      for (const json& i : f.at("instances")) {
        InstanceTrack t;
        for (const json& joint : i.at("joints")) {
          t.joint_names.push_back(joint.at("name").get<std::string>());
          glm::dmat4 m;
          for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = joint.at("m").at(std::size_t(c * 4 + r)).get<double>();
          t.joints.push_back(m);
        }
        for (const json& v : i.at("vertices")) t.vertices.emplace_back(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
        for (const json& p : i.at("proxies"))
          t.proxies.emplace_back(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>(), p.at(3).get<double>());
        frame.instances.push_back(std::move(t));
      }
      tracks.push_back(std::move(frame));
    }
    return tracks;
  } catch (const json::exception& e) {
    return make_error(where + ": not a tracks file: " + e.what());
  }
}

void compare_tracks(const Tracks& actual, const Tracks& golden, const Check& check, double scale, CheckResult& result) {
  const TrackTolerance& tol = check.tracks;
  result.metric = "worst error / tolerance";
  result.threshold = 1.0;
  result.outcome = Outcome::pass;
  std::string first_problem;
  double worst_overall = 0.0;
  for (std::size_t f = 0; f < actual.size(); ++f) {
    const FrameTrack& a = actual[f];
    const FrameTrack* g = f < golden.size() && golden[f].frame == a.frame ? &golden[f] : nullptr;
    double worst = 0.0;
    std::string problem;
    auto consider = [&](double mm, double tolerance_mm, const std::string& what) {
      const double ratio = mm / (tolerance_mm * scale);
      if (ratio > worst) {
        worst = ratio;
        if (ratio > 1.0) problem = format("%s diverges from frame %d by %.3f mm (tolerance %.3f mm)", what, a.frame, mm, tolerance_mm * scale);
      }
    };
    if (g == nullptr || g->instances.size() != a.instances.size()) {
      worst = 1e9;
      problem = "frame " + std::to_string(a.frame) + ": the golden has no matching frame or instance count";
    } else {
      for (std::size_t i = 0; i < a.instances.size(); ++i) {
        const InstanceTrack& x = a.instances[i];
        const InstanceTrack& y = g->instances[i];
        const std::string who = "instance " + std::to_string(i);
        if (x.joints.size() != y.joints.size() || x.vertices.size() != y.vertices.size()) {
          worst = 1e9;
          problem = who + ": joint or vertex count changed at frame " + std::to_string(a.frame);
          continue;
        }
        if (x.proxies.size() != y.proxies.size()) {
          worst = 1e9;
          const long delta = long(x.proxies.size()) - long(y.proxies.size());
          problem = who + ": " + std::to_string(std::labs(delta)) + (delta > 0 ? " proxies appeared" : " proxies disappeared") +
                    " at frame " + std::to_string(a.frame) + " (" + std::to_string(y.proxies.size()) + " -> " +
                    std::to_string(x.proxies.size()) + ")";
          continue;
        }
        for (std::size_t k = 0; k < x.joints.size(); ++k) {
          const double mm = 1000.0 * (glm::length(glm::dvec3(x.joints[k][3]) - glm::dvec3(y.joints[k][3])) +
                                      rotation_displacement(x.joints[k], y.joints[k], tol.rotation_distance_m));
          consider(mm, tol.joint_mm, who + " joint " + x.joint_names[k]);
        }
        for (std::size_t k = 0; k < x.vertices.size(); ++k)
          consider(1000.0 * glm::length(x.vertices[k] - y.vertices[k]), tol.vertex_mm, who + " vertex sample " + std::to_string(k));
        for (std::size_t k = 0; k < x.proxies.size(); ++k) {
          consider(1000.0 * glm::length(glm::dvec3(x.proxies[k]) - glm::dvec3(y.proxies[k])), tol.proxy_mm,
                   who + " proxy " + std::to_string(k) + " center");
          consider(1000.0 * std::abs(x.proxies[k].w - y.proxies[k].w), tol.proxy_mm, who + " proxy " + std::to_string(k) + " radius");
        }
      }
    }
    const bool failed = worst > 1.0;
    result.series.push_back({a.frame, std::min(worst, 1e3), failed});
    worst_overall = std::max(worst_overall, worst);
    if (failed) {
      result.details.push_back(problem);
      if (result.first_failing_frame < 0) {
        result.first_failing_frame = a.frame;
        first_problem = problem;
      }
    }
  }
  if (result.first_failing_frame >= 0) {
    result.outcome = Outcome::fail;
    result.message = first_problem;
  } else {
    char line[128];
    std::snprintf(line, sizeof(line), "%zu frames within tolerance (worst %.1f %% of it)", actual.size(), 100.0 * worst_overall);
    result.message = line;
  }
}

}  // namespace proxygi::regress
