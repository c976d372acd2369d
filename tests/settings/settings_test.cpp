// The settings table (settings/fields.h): one row per member, each row reads and writes its own
// member, limits and messages, names, and what a change of each field needs.
#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "settings/fields.h"

namespace proxygi::settings {
namespace {

TEST(SettingsFields, OneRowPerMemberEachWritingOnlyItsMember) {
  const RenderSettings defaults;
  std::set<std::string_view> keys;
  for (const Field& field : fields()) {
    EXPECT_TRUE(keys.insert(field.key).second) << "duplicate key " << field.key;
    EXPECT_FALSE(check_value(field, field.get(defaults))) << field.key << ": the default must be valid";
    RenderSettings changed = defaults;
    const double value = field.get(defaults);
    const double other = field.kind == FieldKind::boolean ? 1.0 - value
                         : field.kind == FieldKind::choice ? double(field.choices.back().value == int(value)
                                                                       ? field.choices.front().value
                                                                       : field.choices.back().value)
                         : field.kind == FieldKind::integer && !field.allowed.empty()
                             ? double(field.allowed.front() == int(value) ? field.allowed.back() : field.allowed.front())
                             : value + 1.0;
    field.set(changed, other);
    EXPECT_EQ(field.get(changed), field.kind == FieldKind::real ? double(float(other)) : other) << field.key;  // reals are floats
    EXPECT_NE(changed, defaults) << field.key << " writes no member";
    for (const Field& rest : fields()) {  // every other field still reads its default
      if (rest.key != field.key) {
        EXPECT_EQ(rest.get(changed), rest.get(defaults)) << field.key << " writes " << rest.key;
      }
    }
    EXPECT_EQ(classify_change(defaults, changed), field.needs) << field.key;
  }
  EXPECT_EQ(fields().size(), 24u);  // the members named in fields.cpp's structured binding
}

TEST(SettingsFields, LimitsAndMessages) {
  const Field* order = find_field("sh_order");
  const Field* scale = find_field("receiver_scale");
  const Field* eta = find_field("shadow_eta");
  const Field* tau = find_field("hyb_tau");
  const Field* exposure = find_field("exposure_ev");
  ASSERT_TRUE(order && scale && eta && tau && exposure);
  EXPECT_EQ(*check_value(*order, 7), "must be in 3..6 (got 7)");
  EXPECT_EQ(*check_value(*order, 2), "must be in 3..6 (got 2)");
  EXPECT_FALSE(check_value(*order, kMaxShOrder));
  EXPECT_EQ(*check_value(*scale, 3), "must be 1, 2, 4 or 8 (got 3)");
  for (int k : kReceiverScales) EXPECT_FALSE(check_value(*scale, k));
  EXPECT_EQ(*check_value(*eta, 1.0), "must be > 1 or \"auto\" (got 1)");
  // shadow_eta takes "auto" (kEtaFromLighting); indirect_eta does not.
  const Field* indirect_eta = find_field("indirect_eta");
  ASSERT_TRUE(indirect_eta);
  EXPECT_TRUE(is_auto(*eta, kEtaFromLighting));
  EXPECT_FALSE(check_value(*eta, kEtaFromLighting));
  EXPECT_FALSE(is_auto(*indirect_eta, kEtaFromLighting));
  EXPECT_EQ(*check_value(*indirect_eta, kEtaFromLighting), "must be > 1 (got 0)");
  // Written as a number, the stored form of "auto" is refused: only the string selects it.
  EXPECT_EQ(*check_number(*eta, kEtaFromLighting), "must be > 1 or \"auto\" (got 0)");
  EXPECT_FALSE(check_number(*eta, 20.0));
  EXPECT_EQ(*check_number(*order, 7), "must be in 3..6 (got 7)");
  double named = -1.0;
  EXPECT_FALSE(value_from_name(*eta, "auto", named));
  EXPECT_EQ(named, double(kEtaFromLighting));
  EXPECT_EQ(*value_from_name(*eta, "big", named), "unknown value \"big\" (expected a number or \"auto\")");
  EXPECT_EQ(*value_from_name(*indirect_eta, "auto", named), "expected a number, not \"auto\"");
  EXPECT_FALSE(value_from_name(*find_field("tonemap"), "reinhard", named));
  EXPECT_EQ(named, double(Tonemap::reinhard));
  EXPECT_EQ(*value_from_name(*find_field("tonemap"), "filmic", named), "unknown value \"filmic\"");
  EXPECT_EQ(*check_value(*tau, 0.0), "must be > 0 (got 0)");
  EXPECT_EQ(*check_value(*exposure, std::numeric_limits<double>::infinity()), "must be a finite number");
  EXPECT_FALSE(check_value(*exposure, -3.5));
  // render.quality: "manual" (0, refused as a number), the named levels, or a target in (0, 1].
  const Field* quality = find_field("quality");
  ASSERT_TRUE(quality);
  EXPECT_EQ(quality->object_key, "target_relative_mse");
  EXPECT_FALSE(check_value(*quality, kQualityManual));
  EXPECT_EQ(value_name(*quality, kQualityManual), "manual");
  EXPECT_EQ(value_name(*quality, double(0.009f)), "balanced");
  EXPECT_FALSE(value_name(*quality, 0.0123));
  EXPECT_EQ(*check_number(*quality, 0.0), "must be > 0 or one of \"manual\", \"draft\", \"balanced\", \"high\" (got 0)");
  EXPECT_EQ(*check_number(*quality, 1.5), "must be <= 1 or one of \"manual\", \"draft\", \"balanced\", \"high\" (got 1.5)");
  EXPECT_EQ(*check_value(*quality, -0.01), "must be > 0 or one of \"manual\", \"draft\", \"balanced\", \"high\" (got -0.01)");
  EXPECT_FALSE(check_number(*quality, 0.012));  // draft's value as a number
  EXPECT_FALSE(value_from_name(*quality, "high", named));
  EXPECT_EQ(named, double(0.007f));
  EXPECT_EQ(*value_from_name(*quality, "best", named),
            "unknown value \"best\" (expected {\"target_relative_mse\": number} or one of \"manual\", \"draft\", "
            "\"balanced\", \"high\")");
  EXPECT_TRUE(accepts_names(*quality));
  EXPECT_FALSE(accepts_names(*indirect_eta));
  RenderSettings bad;
  bad.receiver_scale = 5;
  EXPECT_EQ(*check_settings(bad), "receiver_scale: must be 1, 2, 4 or 8 (got 5)");
  EXPECT_FALSE(check_settings(RenderSettings{}));
  EXPECT_EQ(find_field("no such field"), nullptr);
}

TEST(SettingsFields, NamesRoundTrip) {
  for (const Field& field : fields())
    for (const Choice& choice : field.choices) {
      EXPECT_EQ(choice_value(field, choice.name), choice.value) << field.key;
      EXPECT_EQ(choice_name(field, choice.value), choice.name) << field.key;
    }
  EXPECT_EQ(name_of(ShadingMethod::ambient_occlusion), "ao");
  EXPECT_EQ(name_of(SplatMethod::compute), "compute");
  EXPECT_FALSE(choice_value(*find_field("tonemap"), "filmic"));
  EXPECT_EQ(name_of(VsglSun::automatic), "auto");
  EXPECT_EQ(*choice_value(*find_field("vsgl_sun"), "off"), int(VsglSun::off));
  EXPECT_FALSE(choice_value(*find_field("vsgl_sun"), "on"));
  EXPECT_EQ(name_of(StaticTransfer::l1), "l1");
  EXPECT_EQ(*choice_value(*find_field("static_transfer"), "ratio"), int(StaticTransfer::ratio));
  EXPECT_FALSE(choice_value(*find_field("static_transfer"), "l2"));
  EXPECT_EQ(RenderSettings{}.static_transfer, StaticTransfer::l0);
}

TEST(SettingsChanges, ClassifiedByWhatTheyNeed) {
  const RenderSettings base;
  RenderSettings exposure = base;
  exposure.exposure_ev = 1.0f;
  EXPECT_EQ(classify_change(base, exposure), kNeedConstants);
  RenderSettings order = base;
  order.sh_order = 5;
  EXPECT_EQ(classify_change(base, order), kNeedPipelines | kNeedTables | kNeedTargets);
  RenderSettings transfer = base;
  transfer.static_transfer = StaticTransfer::l1;  // a shader variant and records baked for the lighting
  EXPECT_EQ(classify_change(base, transfer), kNeedPipelines | kNeedTables);
  RenderSettings scale = base;
  scale.receiver_scale = 2;
  EXPECT_EQ(classify_change(base, scale), kNeedTargets);
  RenderSettings eta = base;
  eta.indirect_eta = 12.0f;
  EXPECT_EQ(classify_change(base, eta), kNeedTables | kNeedConstants);
  RenderSettings both = scale;
  both.exposure_ev = 1.0f;
  EXPECT_EQ(classify_change(base, both), kNeedTargets | kNeedConstants);
  EXPECT_EQ(classify_change(base, base), kNeedNothing);
  EXPECT_EQ(describe_needs(kNeedTargets | kNeedConstants), "targets+constants");
  EXPECT_EQ(describe_needs(kNeedNothing), "nothing");
}

}  // namespace
}  // namespace proxygi::settings
