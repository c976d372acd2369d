#pragma once
// Internal to the scene library: typed, path-tracking reads from nlohmann::json. Every read
// names the field path ("characters[1].clip") and every object rejects keys nobody read, so a
// typo fails loudly instead of silently taking a default. Errors are thrown as FieldError and
// turned into a Result at the parse_scene boundary; nothing here escapes the library (the
// regression scenario parser, src/regress/scenario.cpp, reads its files with the same reader).
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace proxygi::scene::detail {

struct FieldError {
  std::string path;     // e.g. "camera.fov_degrees"; empty for the document itself
  std::string message;  // e.g. "expected a number"
};

[[noreturn]] void fail(std::string path, std::string message);

// "a.b" + "c" -> "a.b.c"; "" + "c" -> "c".
std::string join_path(const std::string& parent, std::string_view key);
std::string index_path(const std::string& parent, std::size_t index);

// Leaf conversions; `path` names the value in errors.
double read_double(const nlohmann::json& value, const std::string& path);
float read_float(const nlohmann::json& value, const std::string& path);  // finite, fits a float
int read_int(const nlohmann::json& value, const std::string& path);      // integral JSON number
bool read_bool(const nlohmann::json& value, const std::string& path);
std::string read_string(const nlohmann::json& value, const std::string& path);
glm::vec3 read_vec3(const nlohmann::json& value, const std::string& path);  // [x, y, z]
glm::vec4 read_vec4(const nlohmann::json& value, const std::string& path);  // [x, y, z, w]
const nlohmann::json& expect_array(const nlohmann::json& value, const std::string& path);

template <class Enum, std::size_t N>
Enum parse_enum(const nlohmann::json& value, const std::string& path,
                const std::pair<std::string_view, Enum> (&names)[N]);

// One JSON object being read. Call finish() after the last read to reject unread keys.
class ObjectReader {
 public:
  ObjectReader(const nlohmann::json& value, std::string path);  // fails unless an object

  const std::string& path() const { return path_; }
  std::string field(std::string_view key) const { return join_path(path_, key); }
  bool has(std::string_view key) const;
  // The value for key (marking it read), or nullptr when absent.
  const nlohmann::json* get(std::string_view key);
  const nlohmann::json& require(std::string_view key);  // fails when absent

  float number(std::string_view key, float fallback);
  double number_double(std::string_view key, double fallback);
  int integer(std::string_view key, int fallback);
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, std::string fallback);
  glm::vec3 vec3(std::string_view key, glm::vec3 fallback);

  // Reads a string naming one of `names` (pairs of {name, value}).
  template <class Enum, std::size_t N>
  Enum enumeration(std::string_view key, Enum fallback,
                   const std::pair<std::string_view, Enum> (&names)[N]) {
    const nlohmann::json* value = get(key);
    if (value == nullptr) return fallback;
    return parse_enum(*value, field(key), names);
  }

  // Rejects the first key that was never read, suggesting the closest key that was asked for.
  void finish() const;

 private:
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string, std::less<>> asked_;  // every key looked up, present or not
};

template <class Enum, std::size_t N>
Enum parse_enum(const nlohmann::json& value, const std::string& path,
                const std::pair<std::string_view, Enum> (&names)[N]) {
  const std::string text = read_string(value, path);
  std::string known;
  for (const auto& [name, e] : names) {
    if (name == text) return e;
    known += (known.empty() ? "" : ", ") + std::string(name);
  }
  fail(path, "unknown value \"" + text + "\" (expected one of: " + known + ")");
}

// Edit distance, for "did you mean" hints.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace proxygi::scene::detail
