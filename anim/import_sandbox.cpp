#include "anim/import_sandbox.h"

#include <cstring>
#include <system_error>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"

namespace proxygi::anim::detail {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// RFC 3986 percent-decoding; a malformed escape stays as written (as tinygltf does).
std::string percent_decode(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_value(text[i + 1]) >= 0 && hex_value(text[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex_value(text[i + 1]) * 16 + hex_value(text[i + 2])));
      i += 2;
    } else {
      out.push_back(text[i]);
    }
  }
  return out;
}

bool has_scheme(const std::string& uri) {
  // scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":"
  const std::size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0) return false;
  for (std::size_t i = 0; i < colon; ++i) {
    const char c = uri[i];
    const bool alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alpha && !(i > 0 && ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.'))) return false;
  }
  return true;
}

bool is_inside(const std::filesystem::path& root, const std::filesystem::path& path) {
  const auto relative = path.lexically_relative(root);
  if (relative.empty() || relative.is_absolute()) return false;
  for (const auto& part : relative) {
    if (part == "..") return false;
  }
  return true;
}

// Canonical path of `path` when it lies inside `root` (symbolic links resolved), else empty.
std::filesystem::path confined(const std::filesystem::path& root, const std::filesystem::path& path) {
  if (root.empty() || !path.is_absolute()) return {};
  std::error_code error;
  const auto canonical = std::filesystem::weakly_canonical(path, error);
  if (error || !is_inside(root, canonical)) return {};
  return canonical;
}

bool file_exists(const std::string& path, void* user) {
  const auto* sandbox = static_cast<const Sandbox*>(user);
  const auto inside = confined(sandbox->base_dir, path);
  std::error_code error;
  return !inside.empty() && std::filesystem::is_regular_file(inside, error);
}

std::string expand_file_path(const std::string& path, void*) { return path; }  // never expand

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* sandbox = static_cast<const Sandbox*>(user);
  const auto inside = confined(sandbox->base_dir, path);
  if (inside.empty()) {
    if (err) *err += "outside the model's folder";
    return false;
  }
  auto bytes = read_file(inside, sandbox->max_bytes);
  if (!bytes) {
    if (err) *err += bytes.message();
    return false;
  }
  *out = std::move(*bytes);
  return true;
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "the importer never writes files";
  return false;
}

}  // namespace

Result<std::filesystem::path> resolve_external_uri(const std::filesystem::path& base_dir,
                                                   const std::string& uri) {
  const std::string quoted = "uri \"" + uri + "\"";
  if (uri.empty()) return make_error("uri is empty");
  if (has_scheme(uri)) return make_error(quoted + " has a scheme; only relative paths and data: URIs are allowed");
  const std::string decoded = percent_decode(uri);
  if (decoded.find('\0') != std::string::npos) return make_error(quoted + " contains a NUL byte");
  if (decoded.empty() || decoded[0] == '/' || decoded[0] == '\\' || has_scheme(decoded)) {
    return make_error(quoted + " is absolute; only paths relative to the model's folder are allowed");
  }
  std::size_t start = 0;
  while (start <= decoded.size()) {
    std::size_t end = decoded.find_first_of("/\\", start);
    if (end == std::string::npos) end = decoded.size();
    if (decoded.compare(start, end - start, "..") == 0 && end - start == 2) {
      return make_error(quoted + " escapes the model's folder");
    }
    start = end + 1;
  }
  if (base_dir.empty()) return make_error(quoted + ": external files are not allowed without a model folder");
  std::error_code error;
  const auto root = std::filesystem::weakly_canonical(base_dir, error);
  if (error) return make_error(quoted + ": model folder unavailable: " + error.message());
  const auto inside = confined(root, root / decoded);
  if (inside.empty()) return make_error(quoted + " resolves outside the model's folder");
  return inside;
}

Result<std::vector<std::uint8_t>> read_external_file(const std::filesystem::path& base_dir,
                                                     const std::string& uri, std::uint64_t max_bytes) {
  auto path = resolve_external_uri(base_dir, uri);
  if (!path) return path.error();
  return read_file(*path, max_bytes);
}

tinygltf::FsCallbacks sandbox_callbacks(Sandbox* sandbox) {
  tinygltf::FsCallbacks callbacks{};
  callbacks.FileExists = &file_exists;
  callbacks.ExpandFilePath = &expand_file_path;
  callbacks.ReadWholeFile = &read_whole_file;
  callbacks.WriteWholeFile = &write_whole_file;
  callbacks.user_data = sandbox;
  return callbacks;
}

Status check_uris(std::string_view json_text, const std::filesystem::path& base_dir) {
  const auto json = nlohmann::json::parse(json_text.begin(), json_text.end(), nullptr,
                                          /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object()) return {};
  for (const char* kind : {"buffers", "images"}) {
    const auto list = json.find(kind);
    if (list == json.end() || !list->is_array()) continue;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const auto& object = (*list)[i];
      if (!object.is_object()) continue;
      const auto uri = object.find("uri");
      if (uri == object.end() || !uri->is_string()) continue;
      const std::string text = uri->get<std::string>();
      if (text.rfind("data:", 0) == 0) continue;
      auto resolved = resolve_external_uri(base_dir, text);
      if (!resolved) {
        const std::string name = std::string(kind).substr(0, std::strlen(kind) - 1);
        return error_at(name + " " + std::to_string(i), resolved.message());
      }
    }
  }
  return {};
}

std::string_view glb_json_chunk(const std::uint8_t* bytes, std::size_t size) {
  if (size < 20) return {};
  std::uint32_t chunk_length = 0;
  std::uint32_t chunk_type = 0;
  std::memcpy(&chunk_length, bytes + 12, 4);
  std::memcpy(&chunk_type, bytes + 16, 4);
  if (chunk_type != 0x4E4F534Au || chunk_length > size - 20) return {};
  return std::string_view(reinterpret_cast<const char*>(bytes + 20), chunk_length);
}

}  // namespace proxygi::anim::detail
