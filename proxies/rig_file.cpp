#include "proxies/rig_file.h"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"

namespace proxygi::proxies {
namespace {

using nlohmann::json;

std::string fmt(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", double(v));
  return buf;
}
std::string vec3(const glm::vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%.7g, %.7g, %.7g]", double(v.x), double(v.y), double(v.z));
  return buf;
}

int line_of(std::string_view text, std::size_t byte) {
  int line = 1;
  for (std::size_t i = 0; i < std::min(byte, text.size()); ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

// Line where each element of the top-level "spheres" array starts (JSON text scanner: strings,
// escapes and nesting depth; values are not interpreted).
std::vector<int> sphere_lines(std::string_view text) {
  std::vector<int> lines;
  int depth = 0, line = 1, array_depth = -1;
  bool expecting = false;
  std::string last_key;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') continue;
    if (array_depth >= 0 && depth == array_depth && expecting && c != ']') {
      lines.push_back(line);
      expecting = false;
    }
    if (c == '"') {
      std::size_t j = i + 1;
      std::string s;
      for (; j < text.size() && text[j] != '"'; ++j) {
        if (text[j] == '\\') ++j;
        else if (text[j] == '\n') ++line;
        else s += text[j];
      }
      if (depth == 1) last_key = s;
      i = j;
      continue;
    }
    if (c == '[' || c == '{') {
      ++depth;
      if (c == '[' && depth == 2 && last_key == "spheres" && array_depth < 0) array_depth = depth, expecting = true;
    } else if (c == ']' || c == '}') {
      if (depth == array_depth && c == ']') array_depth = -2;  // done: ignore later arrays
      --depth;
    } else if (c == ',' && depth == array_depth) {
      expecting = true;
    }
  }
  return lines;
}

bool finite3(const json& v) {
  if (!v.is_array() || v.size() != 3) return false;
  for (const json& x : v)
    if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
  return true;
}

}  // namespace

std::string content_hash(std::span<const std::uint8_t> bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ull;
  char buf[32];
  std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
  return buf;
}

Result<std::string> hash_file(const std::filesystem::path& path) {
  Result<std::vector<std::uint8_t>> bytes = read_file(path, 1ull << 31);
  if (!bytes) return bytes.error();
  return content_hash(*bytes);
}

std::vector<std::string> node_name_warnings(const anim::Character& character) {
  // The nodes that can carry spheres: skin joints and mesh nodes.
  std::vector<char> bone(character.nodes.size(), 0);
  for (const anim::Skin& skin : character.skins)
    for (int joint : skin.joints)
      if (joint >= 0 && std::size_t(joint) < bone.size()) bone[std::size_t(joint)] = 1;
  for (std::size_t n = 0; n < character.nodes.size(); ++n)
    if (character.nodes[n].mesh >= 0) bone[n] = 1;
  std::vector<std::string> warnings;
  std::vector<int> unnamed;
  std::unordered_map<std::string, std::vector<int>> named;
  std::vector<std::string> order;
  for (std::size_t n = 0; n < character.nodes.size(); ++n) {
    if (!bone[n]) continue;
    const std::string& name = character.nodes[n].name;
    if (name.empty()) {
      unnamed.push_back(int(n));
      continue;
    }
    auto& list = named[name];
    if (list.empty()) order.push_back(name);
    list.push_back(int(n));
  }
  auto node_list = [](const std::vector<int>& nodes) {
    std::string out;
    for (std::size_t i = 0; i < nodes.size() && i < 8; ++i) {
      if (i > 0) out += ", ";
      out += std::to_string(nodes[i]);
    }
    if (nodes.size() > 8) out += ", ... (" + std::to_string(nodes.size()) + " in all)";
    return out;
  };
  if (!unnamed.empty())
    warnings.push_back(character.source + ": " + std::to_string(unnamed.size()) + " bone node" +
                       (unnamed.size() > 1 ? "s have" : " has") + " no name (nodes " + node_list(unnamed) +
                       "); proxy spheres are bound by node index");
  for (const std::string& name : order)
    if (named[name].size() > 1)
      warnings.push_back(character.source + ": bone name \"" + name + "\" is used by " + std::to_string(named[name].size()) +
                         " nodes (" + node_list(named[name]) + "); proxy spheres are bound by node index");
  return warnings;
}

std::filesystem::path default_rig_path(const std::filesystem::path& model) {
  std::filesystem::path p = model;
  p.replace_extension(".proxies.json");
  return p;
}

std::string rig_to_json(const ProxyRig& rig, const anim::Character& character) {
  (void)character;  // spheres and weights name nodes by index; the names are the rig's own
  std::string out = "{\n";
  out += "  \"schema\": \"proxygi.proxies\",\n  \"version\": " + std::to_string(ProxyRig::kSchemaVersion) + ",\n";
  out += "  \"model\": " + json(rig.model).dump() + ",\n";
  out += "  \"model_hash\": " + json(rig.model_hash).dump() + ",\n";
  out += "  \"binding\": \"" + std::string(binding_name(rig.binding)) + "\",\n";
  out += "  \"tolerance\": " + fmt(rig.tolerance) + ",\n  \"max_spheres\": " + std::to_string(rig.max_spheres) + ",\n";
  out += "  \"diagonal_m\": " + fmt(rig.diagonal) + ",\n";
  if (rig.fit_version > 0) out += "  \"fit_version\": " + std::to_string(rig.fit_version) + ",\n";
  out += "  \"spheres\": [\n";
  for (std::size_t i = 0; i < rig.spheres.size(); ++i) {
    const ProxySphere& s = rig.spheres[i];
    out += "    {\"bone\": " + json(s.bone).dump() + ", \"node\": " + std::to_string(s.node) + ", \"center\": " + vec3(s.center) +
           ", \"radius\": " + fmt(s.radius) + ", \"albedo\": " + vec3(s.albedo);
    if (s.weight_nodes[0] >= 0) {
      // By node index (names may be empty or repeated); [node, weight] pairs.
      out += ", \"weights\": [";
      for (int k = 0; k < kSphereWeights && s.weight_nodes[std::size_t(k)] >= 0; ++k) {
        if (k > 0) out += ", ";
        char pair[64];
        std::snprintf(pair, sizeof pair, "[%d, %.7g]", s.weight_nodes[std::size_t(k)], double(s.weights[std::size_t(k)]));
        out += pair;
      }
      out += "]";
    }
    out += i + 1 < rig.spheres.size() ? "},\n" : "}\n";
  }
  out += "  ],\n";
  json fit = {{"seconds", rig.fit_seconds}, {"warnings", rig.warnings}};
  if (rig.has_quality)
    fit["quality"] = {{"coverage", rig.quality.coverage},
                      {"outside_volume_ratio", rig.quality.outside_volume_ratio},
                      {"hausdorff_surface_to_spheres_m", rig.quality.hausdorff_surface_to_spheres},
                      {"hausdorff_spheres_to_surface_m", rig.quality.hausdorff_spheres_to_surface},
                      {"mean_surface_to_spheres_m", rig.quality.mean_surface_to_spheres}};
  fit["tracking"] = {{"frames", rig.frames_evaluated},
                     {"rigid_worst_poke_out_m", rig.rigid_error.worst_poke_out},
                     {"rigid_mean_poke_out_m", rig.rigid_error.mean_poke_out},
                     {"blended_worst_poke_out_m", rig.blended_error.worst_poke_out},
                     {"blended_mean_poke_out_m", rig.blended_error.mean_poke_out}};
  out += "  \"fit\": " + fit.dump() + "\n}\n";
  return out;
}

Status write_rig(const std::filesystem::path& path, const ProxyRig& rig, const anim::Character& character) {
  return write_file_atomically(path, rig_to_json(rig, character));
}

namespace {

Result<ProxyRig> parse_rig_document(std::string_view text, const std::string& file_name,
                                    const anim::Character& character) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    return make_error(file_name + ":" + std::to_string(line_of(text, e.byte > 0 ? e.byte - 1 : 0)) + ": not valid JSON (" + e.what() + ")");
  }
  auto top = [&](const std::string& what) { return make_error(file_name + ": " + what); };
  if (!root.is_object()) return top("top level must be an object");
  if (root.value("schema", std::string()) != "proxygi.proxies") return top("\"schema\" must be \"proxygi.proxies\"");
  if (!root.contains("version") || !root["version"].is_number_integer()) return top("\"version\" must be an integer");
  const int version = root["version"].get<int>();
  if (version < 1 || version > ProxyRig::kSchemaVersion)
    return top("schema version " + std::to_string(version) + " is not supported (this proxygi reads versions 1 to " +
               std::to_string(ProxyRig::kSchemaVersion) + ")");
  ProxyRig rig;
  rig.model = root.value("model", std::string());
  rig.model_hash = root.value("model_hash", std::string());
  const std::string binding = root.value("binding", std::string("blended"));
  if (binding != "rigid" && binding != "blended") return top("\"binding\" must be \"rigid\" or \"blended\"");
  rig.binding = binding == "rigid" ? Binding::rigid : Binding::blended;
  if (root.contains("tolerance") && root["tolerance"].is_number()) rig.tolerance = root["tolerance"].get<float>();
  if (root.contains("max_spheres") && root["max_spheres"].is_number_integer()) rig.max_spheres = root["max_spheres"].get<int>();
  if (root.contains("diagonal_m") && root["diagonal_m"].is_number()) rig.diagonal = root["diagonal_m"].get<float>();
  if (root.contains("fit_version") && root["fit_version"].is_number_integer()) rig.fit_version = root["fit_version"].get<int>();
  if (!root.contains("spheres") || !root["spheres"].is_array()) return top("\"spheres\" must be an array");
  // The informational "fit" block is read leniently: a hand edit there never blocks loading.
  if (root.contains("fit") && root["fit"].is_object()) {
    const json& fit = root["fit"];
    auto number = [](const json& o, const char* key) {
      return o.contains(key) && o[key].is_number() ? o[key].get<double>() : 0.0;
    };
    rig.fit_seconds = number(fit, "seconds");
    if (fit.contains("warnings") && fit["warnings"].is_array())
      for (const json& w : fit["warnings"]) if (w.is_string()) rig.warnings.push_back(w.get<std::string>());
    if (fit.contains("quality") && fit["quality"].is_object()) {
      const json& q = fit["quality"];
      rig.has_quality = true;
      rig.quality.coverage = float(number(q, "coverage"));
      rig.quality.outside_volume_ratio = float(number(q, "outside_volume_ratio"));
      rig.quality.hausdorff_surface_to_spheres = float(number(q, "hausdorff_surface_to_spheres_m"));
      rig.quality.hausdorff_spheres_to_surface = float(number(q, "hausdorff_spheres_to_surface_m"));
      rig.quality.mean_surface_to_spheres = float(number(q, "mean_surface_to_spheres_m"));
    }
    if (fit.contains("tracking") && fit["tracking"].is_object()) {
      const json& t = fit["tracking"];
      rig.frames_evaluated = int(number(t, "frames"));
      rig.rigid_error = {float(number(t, "rigid_worst_poke_out_m")), float(number(t, "rigid_mean_poke_out_m"))};
      rig.blended_error = {float(number(t, "blended_worst_poke_out_m")), float(number(t, "blended_mean_poke_out_m"))};
    }
  }

  std::unordered_map<std::string, std::vector<int>> nodes_named;
  for (std::size_t n = 0; n < character.nodes.size(); ++n) nodes_named[character.nodes[n].name].push_back(int(n));
  const std::vector<int> lines = sphere_lines(text);
  const json& spheres = root["spheres"];
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const int line = i < lines.size() ? lines[i] : 0;
    auto bad = [&](const std::string& what) {
      return make_error(file_name + ":" + std::to_string(line) + ": sphere " + std::to_string(i) + ": " + what);
    };
    const json& e = spheres[i];
    if (!e.is_object()) return bad("must be an object");
    ProxySphere s;
    s.source_line = line;
    // Bound by node index; the name is for people and a check that the node is still that bone.
    if (e.contains("bone") && !e["bone"].is_string()) return bad("\"bone\" must be a node name");
    if (e.contains("bone")) s.bone = e["bone"].get<std::string>();
    if (e.contains("node")) {
      if (!e["node"].is_number_integer()) return bad("\"node\" must be an integer");
      const long long node = e["node"].get<long long>();
      if (node < 0 || node >= static_cast<long long>(character.nodes.size()))
        return bad("node " + std::to_string(node) + " is out of range (" + character.source + " has " +
                   std::to_string(character.nodes.size()) + " nodes)");
      s.node = int(node);
      const std::string& actual = character.nodes[std::size_t(node)].name;
      if (e.contains("bone") && actual != s.bone)
        return bad("node " + std::to_string(node) + " is not named \"" + s.bone + "\" (it is \"" + actual +
                   "\"; was the model changed?)");
      s.bone = actual;
    } else {
      if (!e.contains("bone")) return bad("needs \"node\" (a node index) or \"bone\" (a unique node name)");
      const auto named = nodes_named.find(s.bone);
      if (named == nodes_named.end()) return bad("bone \"" + s.bone + "\" is not a node of " + character.source);
      if (named->second.size() > 1)
        return bad("bone \"" + s.bone + "\" names " + std::to_string(named->second.size()) +
                   " nodes of " + character.source + "; give \"node\" (its index)");
      s.node = named->second.front();
    }
    if (!e.contains("center") || !finite3(e["center"])) return bad("\"center\" must be 3 finite numbers");
    s.center = glm::vec3(e["center"][0].get<float>(), e["center"][1].get<float>(), e["center"][2].get<float>());
    if (!e.contains("radius") || !e["radius"].is_number() || !std::isfinite(e["radius"].get<double>()))
      return bad("\"radius\" must be a finite number");
    s.radius = e["radius"].get<float>();
    if (!(s.radius > 0.0f)) return bad("radius must be > 0");
    if (e.contains("albedo")) {
      if (!finite3(e["albedo"])) return bad("\"albedo\" must be 3 finite numbers");
      s.albedo = glm::vec3(e["albedo"][0].get<float>(), e["albedo"][1].get<float>(), e["albedo"][2].get<float>());
      if (s.albedo.r < 0.0f || s.albedo.g < 0.0f || s.albedo.b < 0.0f) return bad("albedo must be >= 0");
    }
    if (e.contains("weights")) {
      // [[node, weight], ...] (version 2), or {"unique node name": weight, ...} (version 1).
      const json& w = e["weights"];
      if (!w.is_object() && !w.is_array())
        return bad("\"weights\" must be [[node index, weight], ...] or {\"node name\": weight}");
      if (w.size() > std::size_t(kSphereWeights)) return bad("at most 4 weights");
      std::vector<std::pair<int, float>> entries;
      float total = 0.0f;
      auto add = [&](int node, const std::string& label, const json& value) -> Status {
        if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0.0)
          return make_error("weight of " + label + " must be a finite number >= 0");
        for (const auto& [other, unused] : entries)
          if (other == node) return make_error("node " + std::to_string(node) + " is weighted twice");
        entries.emplace_back(node, value.get<float>());
        total += value.get<float>();
        return {};
      };
      if (w.is_array()) {
        for (const json& pair : w) {
          if (!pair.is_array() || pair.size() != 2 || !pair[0].is_number_integer())
            return bad("each weight must be [node index, weight]");
          const long long node = pair[0].get<long long>();
          if (node < 0 || node >= static_cast<long long>(character.nodes.size()))
            return bad("weight node " + std::to_string(node) + " is out of range (" + character.source + " has " +
                       std::to_string(character.nodes.size()) + " nodes)");
          if (Status added = add(int(node), "node " + std::to_string(node), pair[1]); !added) return bad(added.message());
        }
      } else {
        for (const auto& [name, value] : w.items()) {
          const auto node = nodes_named.find(name);
          if (node == nodes_named.end()) return bad("weight bone \"" + name + "\" is not a node of " + character.source);
          if (node->second.size() > 1)
            return bad("weight bone \"" + name + "\" names " + std::to_string(node->second.size()) +
                       " nodes; weight by node index: [[node, weight], ...]");
          if (Status added = add(node->second.front(), "\"" + name + "\"", value); !added) return bad(added.message());
        }
      }
      if (!entries.empty()) {
        if (!(total > 0.0f)) return bad("weights must have a positive sum");
        std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
        for (std::size_t k = 0; k < entries.size(); ++k) {
          s.weight_nodes[k] = entries[k].first;
          s.weights[k] = entries[k].second / total;
        }
      }
    }
    rig.spheres.push_back(s);
  }
  return rig;
}

}  // namespace

Result<ProxyRig> parse_rig(std::string_view text, const std::string& file_name, const anim::Character& character) {
  // nlohmann throws for what the checks above do not reach (a number too large for a double,
  // found by fuzz_rig_parse): every such input is a clear error, never a crash.
  try {
    return parse_rig_document(text, file_name, character);
  } catch (const json::exception& e) {
    return make_error(file_name + ": invalid rig file (" + std::string(e.what()) + ")");
  }
}

Result<ProxyRig> read_rig(const std::filesystem::path& path, const anim::Character& character) {
  Result<std::vector<std::uint8_t>> bytes = read_file(path, 1ull << 28);
  if (!bytes) return bytes.error();
  const std::string_view text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
  return parse_rig(text, path.string(), character);
}

}  // namespace proxygi::proxies
