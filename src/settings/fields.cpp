#include "settings/fields.h"

#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>
#include <vector>

namespace proxygi::settings {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <auto Member>
double get_member(const RenderSettings& settings) {
  const auto value = settings.*Member;
  if constexpr (std::is_enum_v<decltype(value)>) return double(int(value));
  else return double(value);
}

template <auto Member>
void set_member(RenderSettings& settings, double value) {
  using T = std::remove_reference_t<decltype(settings.*Member)>;
  if constexpr (std::is_enum_v<T>) settings.*Member = T(int(value));
  else if constexpr (std::is_same_v<T, bool>) settings.*Member = value != 0.0;
  else settings.*Member = T(value);
}

// The choices of an enum in its name table's order.
template <class Enum, std::size_t N>
constexpr std::array<Choice, N> choices_of(const Name<Enum> (&names)[N]) {
  std::array<Choice, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = {names[i].first, int(names[i].second)};
  return out;
}

constexpr auto kMethodChoices = choices_of(kShadingMethodNames);
constexpr auto kOperatorChoices = choices_of(kIndirectOperatorNames);
constexpr auto kIndirectMethodChoices = choices_of(kIndirectMethodNames);
constexpr auto kVsglGroupingChoices = choices_of(kVsglGroupingNames);
constexpr auto kVsglSunChoices = choices_of(kVsglSunNames);
constexpr auto kExponentialChoices = choices_of(kExponentialNames);
constexpr auto kUpsamplingChoices = choices_of(kUpsamplingNames);
constexpr auto kSplatChoices = choices_of(kSplatMethodNames);
constexpr auto kTonemapChoices = choices_of(kTonemapNames);
constexpr auto kStaticTransferChoices = choices_of(kStaticTransferNames);
constexpr auto kAntialiasingChoices = choices_of(kAntialiasingNames);
constexpr auto kProxyLodChoices = choices_of(kProxyLodNames);

template <auto Member>
Field choice(std::string_view key, std::string_view description, Needs needs, std::span<const Choice> choices) {
  Field f{key, description, FieldKind::choice, needs};
  f.choices = choices;
  f.get = &get_member<Member>;
  f.set = &set_member<Member>;
  return f;
}

template <auto Member>
Field boolean(std::string_view key, std::string_view description, Needs needs) {
  Field f{key, description, FieldKind::boolean, needs};
  f.get = &get_member<Member>;
  f.set = &set_member<Member>;
  return f;
}

template <auto Member>
Field integer(std::string_view key, std::string_view description, Needs needs, double min, double max,
              std::span<const int> allowed = {}) {
  Field f{key, description, FieldKind::integer, needs};
  f.min = f.ui_min = min;
  f.max = f.ui_max = max;
  f.allowed = allowed;
  f.get = &get_member<Member>;
  f.set = &set_member<Member>;
  return f;
}

// A real with min exclusive (> min) when min is finite.
template <auto Member>
Field real(std::string_view key, std::string_view description, Needs needs, double min, double ui_min, double ui_max) {
  Field f{key, description, FieldKind::real, needs};
  f.min = min;
  f.min_exclusive = std::isfinite(min);
  f.max = kInfinity;
  f.ui_min = ui_min;
  f.ui_max = ui_max;
  f.get = &get_member<Member>;
  f.set = &set_member<Member>;
  return f;
}

// render.quality's names, in kQualityLevels' order.
constexpr auto kQualityNamed = [] {
  std::array<NamedValue, std::size(kQualityLevels)> out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {kQualityLevels[i].first, double(kQualityLevels[i].second)};
  return out;
}();

Field quality_field() {
  Field f = real<&RenderSettings::quality>(
      "quality", "manual, or a target relative MSE the renderer chooses order, k, upsampling and eta for",
      kNeedConstants, 0.0, 0.005, 0.05);
  f.max = kMaxQualityTarget;
  f.named = kQualityNamed;
  f.object_key = kQualityTargetKey;
  return f;
}

Field with_auto(Field field) {
  field.accepts_auto = true;
  return field;
}

const std::vector<Field>& table() {
  using S = RenderSettings;
  static const std::vector<Field> fields = {
      choice<&S::method>("method", "image: proxy accumulation at 1/k receivers; vertex, ao: the baselines",
                         kNeedPipelines | kNeedTargets, kMethodChoices),
      integer<&S::sh_order>("sh_order", "SH order of shadows (n bands, n² coefficients)",
                            kNeedPipelines | kNeedTables | kNeedTargets, kMinShOrder, kMaxShOrder),
      integer<&S::receiver_scale>("receiver_scale", "k: receivers at 1/k of the display per axis", kNeedTargets,
                                  kReceiverScales.front(), kReceiverScales.back(), kReceiverScales),
      with_auto(real<&S::shadow_eta>("shadow_eta", "η of shadows: sphere of influence in proxy radii (auto: from the lighting)",
                                     kNeedTables | kNeedConstants, 1.0, 1.5, 40.0)),
      real<&S::indirect_eta>("indirect_eta", "η of indirect light: sphere of influence in proxy radii",
                             kNeedTables | kNeedConstants, 1.0, 1.5, 40.0),
      boolean<&S::sh_window>("sh_window", "ringing window on the SH lighting", kNeedTables),
      choice<&S::indirect_operator>("indirect_operator", "how a proxy's bounce light is formed", kNeedPipelines,
                                    kOperatorChoices),
      choice<&S::exponential>("exponential", "SH exponential: hyb (halve, OL, square) or ol alone", kNeedConstants,
                              kExponentialChoices),
      real<&S::hyb_tau>("hyb_tau", "HYB: halve until the log vector's norm is at most τ", kNeedConstants, 0.0, 0.01, 2.0),
      choice<&S::upsampling>("upsampling", "receivers to display: joint-bilateral (eq. 11) or bilinear", kNeedConstants,
                             kUpsamplingChoices),
      real<&S::bilateral_depth_epsilon>("bilateral_depth_epsilon", "ε of the bilateral depth weight: tangent-plane distance / eye depth",
                                        kNeedConstants, 0.0, 0.001, 1.0),
      choice<&S::splat>("splat", "log-occlusion accumulation: tiled compute gather or raster splat", kNeedPipelines,
                        kSplatChoices),
      choice<&S::indirect_method>("indirect_method", "bounce light: proxy (spheres), vsgl (SG lights) or none",
                                  kNeedPipelines | kNeedConstants, kIndirectMethodChoices),
      integer<&S::vsgl_lights>("vsgl_lights", "vsgl: lights per character (its triangles in as many groups)",
                               kNeedConstants, kVsglLightsPerCharacter.front(), kVsglLightsPerCharacter.back(),
                               kVsglLightsPerCharacter),
      choice<&S::vsgl_grouping>("vsgl_grouping", "vsgl: a character's lights by index range or by bone group",
                                kNeedConstants, kVsglGroupingChoices),
      choice<&S::vsgl_sun>("vsgl_sun", "vsgl: the sun's bounce from a reflective shadow map (auto: sun above the horizon) or off",
                           kNeedPipelines | kNeedTables, kVsglSunChoices),
      boolean<&S::ground_bounce>("ground_bounce", "light bounced off the lit ground onto receivers above it", kNeedTables),
      boolean<&S::mask_sender_light>("mask_sender_light",
                                     "proxies reflect only the light from above the receiver's tangent plane (false: the whole environment)",
                                     kNeedTables),
      choice<&S::tonemap>("tonemap", "display curve", kNeedConstants, kTonemapChoices),
      real<&S::exposure_ev>("exposure_ev", "exposure in stops before the tonemap", kNeedConstants, -kInfinity, -8.0, 8.0),
      // Tables: the static receivers' records are baked for the frame's lighting with the tables.
      choice<&S::static_transfer>("static_transfer",
                                  "static meshes' PRT: l0 (no static self-shadowing), ratio or l1 (proxies × static transfer)",
                                  kNeedPipelines | kNeedTables, kStaticTransferChoices),
      choice<&S::antialiasing>("antialiasing", "supersampling: shade f × f samples per pixel (ssaa2, ssaa4) and box-filter them, or off",
                               kNeedTargets | kNeedConstants, kAntialiasingChoices),
      choice<&S::proxy_lod>("proxy_lod", "proxy levels of detail: off (whole rigs) or auto (by projected size, cross-faded)",
                            kNeedConstants, kProxyLodChoices),
      quality_field(),
  };
  return fields;
}

// Every member of RenderSettings needs a row: this structured binding names each member once, so a
// new member stops the build here until its row is added and it is named below too.
[[maybe_unused]] void every_member_has_a_row(const RenderSettings& settings) {
  const auto& [method, sh_order, receiver_scale, shadow_eta, indirect_eta, sh_window, indirect_operator, exponential,
               hyb_tau, upsampling, bilateral_depth_epsilon, splat, indirect_method, vsgl_lights, vsgl_grouping,
               vsgl_sun, ground_bounce, mask_sender_light, tonemap, exposure_ev, static_transfer, antialiasing,
               proxy_lod, quality] = settings;
  (void)method, (void)sh_order, (void)receiver_scale, (void)shadow_eta, (void)indirect_eta, (void)sh_window;
  (void)indirect_operator, (void)exponential, (void)hyb_tau, (void)upsampling, (void)bilateral_depth_epsilon;
  (void)splat, (void)indirect_method, (void)vsgl_lights, (void)vsgl_grouping, (void)vsgl_sun, (void)ground_bounce, (void)mask_sender_light, (void)tonemap;
  (void)exposure_ev, (void)static_transfer, (void)antialiasing, (void)proxy_lod, (void)quality;
}

std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string list_allowed(std::span<const int> allowed) {
  std::string out;
  for (std::size_t i = 0; i < allowed.size(); ++i) {
    if (i > 0) out += i + 1 == allowed.size() ? " or " : ", ";
    out += std::to_string(allowed[i]);
  }
  return out;
}

}  // namespace

std::span<const Field> fields() { return table(); }

const Field* find_field(std::string_view key) {
  for (const Field& field : table())
    if (field.key == key) return &field;
  return nullptr;
}

bool is_auto(const Field& field, double value) { return field.accepts_auto && value == double(kEtaFromLighting); }

std::optional<std::string_view> value_name(const Field& field, double value) {
  if (is_auto(field, value)) return kAutoName;
  for (const NamedValue& named : field.named)
    if (named.value == value) return named.name;
  return std::nullopt;
}

bool accepts_names(const Field& field) {
  return field.kind == FieldKind::choice || field.accepts_auto || !field.named.empty();
}

namespace {

// `or "auto"` / `or one of "manual", "draft"` for range messages of fields that take names.
std::string or_names(const Field& field) {
  if (field.accepts_auto) return " or \"auto\"";
  if (field.named.empty()) return "";
  std::string out = " or one of ";
  for (std::size_t i = 0; i < field.named.size(); ++i) {
    if (i > 0) out += ", ";
    out += '"';
    out += field.named[i].name;
    out += '"';
  }
  return out;
}

// check_value without the names: the number's own range.
std::optional<std::string> check_plain(const Field& field, double value) {
  switch (field.kind) {
    case FieldKind::boolean:
      if (value != 0.0 && value != 1.0) return "must be true or false";
      return std::nullopt;
    case FieldKind::choice:
      for (const Choice& choice : field.choices)
        if (double(choice.value) == value) return std::nullopt;
      return "is not one of its names (got " + show(value) + ")";
    case FieldKind::integer: {
      const int integer = int(value);
      if (!field.allowed.empty()) {
        for (int allowed : field.allowed)
          if (double(allowed) == value) return std::nullopt;
        return "must be " + list_allowed(field.allowed) + " (got " + std::to_string(integer) + ")";
      }
      if (value < field.min || value > field.max)
        return "must be in " + show(field.min) + ".." + show(field.max) + " (got " + std::to_string(integer) + ")";
      return std::nullopt;
    }
    case FieldKind::real:
      if (!std::isfinite(value)) return std::string("must be a finite number");
      if (field.min_exclusive && !(value > field.min))
        return "must be > " + show(field.min) + or_names(field) + " (got " + show(value) + ")";
      if (value > field.max) return "must be <= " + show(field.max) + or_names(field) + " (got " + show(value) + ")";
      return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_value(const Field& field, double value) {
  if (value_name(field, value)) return std::nullopt;
  return check_plain(field, value);
}

std::optional<std::string> check_number(const Field& field, double value) {
  if (is_auto(field, value)) return "must be > " + show(field.min) + " or \"auto\" (got " + show(value) + ")";
  if (field.kind == FieldKind::real) return check_plain(field, value);
  return check_value(field, value);
}

std::optional<std::string> value_from_name(const Field& field, std::string_view text, double& value) {
  std::string quoted = "\"";  // appended piecewise: GCC 12's -Wrestrict misfires on a + b here
  quoted += text;
  quoted += '"';
  if (field.kind == FieldKind::choice) {
    if (auto chosen = choice_value(field, text)) {
      value = double(*chosen);
      return std::nullopt;
    }
    return "unknown value " + quoted;
  }
  if (field.accepts_auto) {
    if (text == kAutoName) {
      value = double(kEtaFromLighting);
      return std::nullopt;
    }
    return "unknown value " + quoted + " (expected a number or \"auto\")";
  }
  if (!field.named.empty()) {
    for (const NamedValue& named : field.named)
      if (named.name == text) {
        value = named.value;
        return std::nullopt;
      }
    std::string expected = " (expected";
    if (!field.object_key.empty()) {
      expected += " {\"";
      expected += field.object_key;
      expected += "\": number}";
    } else {
      expected += " a number";
    }
    return "unknown value " + quoted + expected + or_names(field) + ")";
  }
  return "expected a number, not " + quoted;
}

std::optional<std::string> check_settings(const RenderSettings& settings) {
  for (const Field& field : table())
    if (auto reason = check_value(field, field.get(settings))) return std::string(field.key) + ": " + *reason;
  return std::nullopt;
}

std::string_view choice_name(const Field& field, int value) {
  for (const Choice& choice : field.choices)
    if (choice.value == value) return choice.name;
  return "?";
}

std::optional<int> choice_value(const Field& field, std::string_view name) {
  for (const Choice& choice : field.choices)
    if (choice.name == name) return choice.value;
  return std::nullopt;
}

Needs classify_change(const RenderSettings& before, const RenderSettings& after) {
  Needs needs = kNeedNothing;
  for (const Field& field : table())
    if (field.get(before) != field.get(after)) needs |= field.needs;
  return needs;
}

std::string describe_needs(Needs needs) {
  if (needs == kNeedNothing) return "nothing";
  std::string out;
  const std::pair<Need, const char*> names[] = {
      {kNeedPipelines, "pipelines"}, {kNeedTargets, "targets"}, {kNeedTables, "tables"}, {kNeedConstants, "constants"}};
  for (const auto& [need, name] : names)
    if (needs & need) {
      if (!out.empty()) out += '+';  // appended piecewise: GCC 12's -Wrestrict misfires on a + b here
      out += name;
    }
  return out;
}

}  // namespace proxygi::settings
