#include "scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace proxygi::scene::detail {

using nlohmann::json;

void fail(std::string path, std::string message) {
  throw FieldError{std::move(path), std::move(message)};
}

std::string join_path(const std::string& parent, std::string_view key) {
  if (parent.empty()) return std::string(key);
  return parent + "." + std::string(key);
}

std::string index_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

namespace {

const char* type_name(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "an integer";
    case json::value_t::number_float: return "a number";
    default: return "an unsupported value";
  }
}

[[noreturn]] void fail_type(const json& value, const std::string& path, std::string_view expected) {
  fail(path, "expected " + std::string(expected) + ", got " + type_name(value));
}

}  // namespace

double read_double(const json& value, const std::string& path) {
  if (!value.is_number()) fail_type(value, path, "a number");
  const double d = value.get<double>();
  if (!std::isfinite(d)) fail(path, "expected a finite number");
  return d;
}

float read_float(const json& value, const std::string& path) {
  const double d = read_double(value, path);
  if (std::fabs(d) > static_cast<double>(std::numeric_limits<float>::max())) {
    fail(path, "number out of range");
  }
  return static_cast<float>(d);
}

int read_int(const json& value, const std::string& path) {
  if (value.is_number_integer()) {  // signed or unsigned
    if (value.is_number_unsigned()) {
      const auto u = value.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
        fail(path, "integer out of range");
      }
      return static_cast<int>(u);
    }
    const auto i = value.get<std::int64_t>();
    if (i < std::numeric_limits<int>::min() || i > std::numeric_limits<int>::max()) {
      fail(path, "integer out of range");
    }
    return static_cast<int>(i);
  }
  fail_type(value, path, "an integer");
}

bool read_bool(const json& value, const std::string& path) {
  if (!value.is_boolean()) fail_type(value, path, "true or false");
  return value.get<bool>();
}

std::string read_string(const json& value, const std::string& path) {
  if (!value.is_string()) fail_type(value, path, "a string");
  return value.get<std::string>();
}

const json& expect_array(const json& value, const std::string& path) {
  if (!value.is_array()) fail_type(value, path, "an array");
  return value;
}

namespace {

template <int N>
glm::vec<N, float> read_vector(const json& value, const std::string& path) {
  if (!value.is_array() || value.size() != static_cast<std::size_t>(N)) {
    fail(path, "expected an array of " + std::to_string(N) + " numbers");
  }
  glm::vec<N, float> v(0.0f);
  for (int i = 0; i < N; ++i) {
    v[i] = read_float(value[static_cast<std::size_t>(i)], index_path(path, static_cast<std::size_t>(i)));
  }
  return v;
}

}  // namespace

glm::vec3 read_vec3(const json& value, const std::string& path) { return read_vector<3>(value, path); }
glm::vec4 read_vec4(const json& value, const std::string& path) { return read_vector<4>(value, path); }

ObjectReader::ObjectReader(const json& value, std::string path)
    : object_(value), path_(std::move(path)) {
  if (!value.is_object()) fail_type(value, path_.empty() ? std::string("(document)") : path_, "an object");
}

bool ObjectReader::has(std::string_view key) const {
  return object_.find(std::string(key)) != object_.end();
}

const json* ObjectReader::get(std::string_view key) {
  asked_.emplace(key);
  const auto it = object_.find(std::string(key));
  return it == object_.end() ? nullptr : &*it;
}

const json& ObjectReader::require(std::string_view key) {
  const json* value = get(key);
  if (value == nullptr) fail(field(key), "required field is missing");
  return *value;
}

float ObjectReader::number(std::string_view key, float fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_float(*value, field(key));
}

double ObjectReader::number_double(std::string_view key, double fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_double(*value, field(key));
}

int ObjectReader::integer(std::string_view key, int fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_int(*value, field(key));
}

bool ObjectReader::boolean(std::string_view key, bool fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_bool(*value, field(key));
}

std::string ObjectReader::string(std::string_view key, std::string fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_string(*value, field(key));
}

glm::vec3 ObjectReader::vec3(std::string_view key, glm::vec3 fallback) {
  const json* value = get(key);
  return value == nullptr ? fallback : read_vec3(*value, field(key));
}

void ObjectReader::finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (asked_.count(key) != 0) continue;
    std::string message = "unknown key";
    std::string_view best;
    std::size_t best_distance = std::numeric_limits<std::size_t>::max();
    for (const std::string& known : asked_) {
      const std::size_t d = edit_distance(key, known);
      // Only near misses: two edits, or a third of the key for long keys ("exposure").
      if (d <= std::max<std::size_t>(2, known.size() / 3) && d < best_distance) {
        best_distance = d;
        best = known;
      }
    }
    if (!best.empty()) message += " (did you mean \"" + std::string(best) + "\"?)";
    fail(field(key), message);
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace proxygi::scene::detail
