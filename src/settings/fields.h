#pragma once
// The render settings as a table of fields: one row per member of RenderSettings, in the order
// the scene file writes them. Parsing, validation and writing of the scene's render block, the
// viewer's settings panel and the tests that change every setting in place walk this table, so a
// new setting is one member, one row here, and its use in the frame.
//
// Every value goes through a double: booleans 0/1, integers and floats exactly, enums by their
// enumerator (see Field::choices for their names).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "settings/render_settings.h"

namespace proxygi::settings {

// What a change of a setting needs the renderer to rebuild, cheapest last. A change needing
// `pipelines` also rebuilds what the pipelines' shaders size (targets, tables) when the field
// says so; the renderer does only what the union of the changed fields' needs says.
enum Need : std::uint32_t {
  kNeedNothing = 0,
  kNeedConstants = 1u << 0,  // frame constants only (τ, exposure, ε, tonemap, switches)
  kNeedTables = 1u << 1,     // the CPU tables and their uploads (η, window, SH order)
  kNeedTargets = 1u << 2,    // render targets and receiver buffers (k, size, SH order, method)
  kNeedPipelines = 1u << 3,  // shader variants (SH order, method, indirect operator, splat)
};
using Needs = std::uint32_t;

enum class FieldKind { boolean, integer, real, choice };

struct Choice {
  std::string_view name;
  int value = 0;  // the enumerator as int
};

// A number a real field also accepts by name (render.quality "manual", "balanced", ...).
struct NamedValue {
  std::string_view name;
  double value = 0.0;
};

struct Field {
  std::string_view key;          // scene-file key under "render"; also the UI label
  std::string_view description;  // one line for tooltips and help
  FieldKind kind = FieldKind::real;
  Needs needs = kNeedConstants;
  // integer: the allowed values (when not empty) or [min, max]; real: min (exclusive when
  // min_exclusive) and max (inclusive, infinite when none), ui_min..ui_max for sliders.
  std::span<const int> allowed;
  double min = 0.0, max = 0.0;
  bool min_exclusive = false;
  double ui_min = 0.0, ui_max = 0.0;
  std::span<const Choice> choices;  // choice: names in the order errors list them
  // real: also the string "auto" in files and a checkbox in the UI, stored as kEtaFromLighting.
  bool accepts_auto = false;
  // real: names for some values (the first may be a sentinel outside [min, max], as "manual" = 0
  // of render.quality; like "auto" it is refused as a number). Written by name when one matches.
  std::span<const NamedValue> named;
  // real: when not empty, files also accept {object_key: number} and write unnamed values so.
  std::string_view object_key;
  double (*get)(const RenderSettings&) = nullptr;
  void (*set)(RenderSettings&, double) = nullptr;
};

std::span<const Field> fields();
const Field* find_field(std::string_view key);

// Why `value` is not allowed for `field` ("must be in 3..6 (got 7)"), or nothing when it is.
std::optional<std::string> check_value(const Field& field, double value);
// Whether `value` is the "auto" of a field that accepts it.
bool is_auto(const Field& field, double value);
// The name of `value` among field.named (or "auto"), or nothing.
std::optional<std::string_view> value_name(const Field& field, double value);
// Whether a file or script may give this field as a string: a choice, "auto" or a named value.
bool accepts_names(const Field& field);
inline constexpr std::string_view kAutoName = "auto";
// A value written as a number (scene file, viewer script, scenario override): check_value, except
// that the stored form of "auto" (kEtaFromLighting, 0) or of a named sentinel ("manual", 0) is
// refused as a number, so `0` is an error and only the string selects it.
std::optional<std::string> check_number(const Field& field, double value);
// A value written as a string: a choice's name, or "auto" for a field that accepts it. The reason
// when `text` is neither ("unknown value \"big\" (expected a number or \"auto\")").
std::optional<std::string> value_from_name(const Field& field, std::string_view text, double& value);
// The first invalid field of `settings` with its reason, as "key: reason"; nothing when valid.
std::optional<std::string> check_settings(const RenderSettings& settings);

// The name of a choice value, or its number when it has none.
std::string_view choice_name(const Field& field, int value);
// The choice of `field` named `name`, or nothing.
std::optional<int> choice_value(const Field& field, std::string_view name);

// What a renderer showing `before` needs to rebuild to show `after` (the union of the changed
// fields' needs); kNeedNothing when they are equal.
Needs classify_change(const RenderSettings& before, const RenderSettings& after);
// "constants", "tables+targets", ...: for logs and the viewer's HUD.
std::string describe_needs(Needs needs);

}  // namespace proxygi::settings
