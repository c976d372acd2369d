// `bench chart --regions`: each mask on hand-made feature images whose answer is drawn in the
// comment, the unshadowed radiance against closed forms, and a row's region scores and bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "sh/basis.h"
#include "study/chart_regions.h"

namespace proxygi::study {
namespace {

ref::ReceiverMask from_rows(const std::vector<std::string>& rows) {
  return ref::mask_where(int(rows.front().size()), int(rows.size()),
                         [&](int x, int y) { return rows[std::size_t(y)][std::size_t(x)] == '#'; });
}

std::vector<std::string> to_rows(const ref::ReceiverMask& mask) {
  std::vector<std::string> rows(std::size_t(mask.height), std::string(std::size_t(mask.width), '.'));
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.contains(std::size_t(y) * std::size_t(mask.width) + std::size_t(x))) rows[std::size_t(y)][std::size_t(x)] = '#';
  return rows;
}

TEST(ChartRegions, ThinRegionIsTheMaskMinusItsOpening) {
  // A 2-px bar (x = 1..2), a 5 × 5 block (x = 5..9, y = 1..5) and a 1-px arm out of the block
  // (x = 10..11, y = 3). Width 4: the bar and the arm are thin, every block pixel lies in a 4 × 4
  // square inside the block.
  const ref::ReceiverMask mask = from_rows({".##.........",
                                            ".##..#####..",
                                            ".##..#####..",
                                            ".##..#######",
                                            ".##..#####..",
                                            ".##..#####..",
                                            ".##........."});
  const std::vector<std::string> expected = {".##.........",
                                             ".##.........",
                                             ".##.........",
                                             ".##.......##",
                                             ".##.........",
                                             ".##.........",
                                             ".##........."};
  EXPECT_EQ(to_rows(thin_region(mask, 4)), expected);
  // Width 2: the bar holds 2 × 2 squares; only the 1-px arm is thin.
  const std::vector<std::string> narrow = {"............", "............", "............", "..........##",
                                           "............", "............", "............"};
  EXPECT_EQ(to_rows(thin_region(mask, 2)), narrow);
  // Width 6: nothing fits, everything is thin.
  EXPECT_EQ(to_rows(thin_region(mask, 6)), to_rows(mask));
}

image::ImageF depth_image(int w, int h, const std::function<float(int, int)>& depth) {
  image::ImageF image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = glm::vec4(glm::vec3(depth(x, y)), 1.0f);
  return image;
}

image::ImageF normal_image(int w, int h, const std::function<glm::vec3(int, int)>& normal) {
  image::ImageF image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = glm::vec4(normal(x, y), 1.0f);
  return image;
}

TEST(ChartRegions, DiscontinuityBandFindsDepthNormalAndBackgroundJumps) {
  const auto up = [](int, int) { return glm::vec3(0, 1, 0); };
  // A plane whose depth grows 2 % per pixel (a grazing ground): no jump of > 10 %, no band.
  const image::ImageF ramp = depth_image(12, 3, [](int x, int) { return 2.0f * std::pow(1.02f, float(x)); });
  EXPECT_EQ(discontinuity_band(ramp, normal_image(12, 3, up), 1, 0.1, 30.0).count(), 0u);
  // Depth 2 left of x = 6, 4 from it: the jump marks x = 5 and 6, radius 1 widens to x = 4..7.
  const image::ImageF step = depth_image(12, 3, [](int x, int) { return x < 6 ? 2.0f : 4.0f; });
  const std::vector<std::string> band = {"....####....", "....####....", "....####...."};
  EXPECT_EQ(to_rows(discontinuity_band(step, normal_image(12, 3, up), 1, 0.1, 30.0)), band);
  // Same depth, the normal turns by 45° at x = 6 (a crease): the same band; by 20°: none.
  const image::ImageF flat = depth_image(12, 3, [](int, int) { return 3.0f; });
  const auto turned = [](float degrees) {
    return [degrees](int x, int) {
      const float a = x < 6 ? 0.0f : degrees * std::numbers::pi_v<float> / 180.0f;
      return glm::vec3(std::sin(a), std::cos(a), 0.0f);
    };
  };
  EXPECT_EQ(to_rows(discontinuity_band(flat, normal_image(12, 3, turned(45.0f)), 1, 0.1, 30.0)), band);
  EXPECT_EQ(discontinuity_band(flat, normal_image(12, 3, turned(20.0f)), 1, 0.1, 30.0).count(), 0u);
  // Background (depth 0) from x = 6: the silhouette marks x = 5 and 6; radius 0 keeps just them.
  const image::ImageF silhouette = depth_image(12, 3, [](int x, int) { return x < 6 ? 3.0f : 0.0f; });
  const std::vector<std::string> thin_band = {".....##.....", ".....##.....", ".....##....."};
  EXPECT_EQ(to_rows(discontinuity_band(silhouette, normal_image(12, 3, up), 0, 0.1, 30.0)), thin_band);
}

ref::PixelFeatures features_with_normals(const std::vector<glm::vec3>& normals, float albedo) {
  ref::PixelFeatures features;
  const int w = int(normals.size());
  features.mask = image::ImageF(w, 1, glm::vec4(1.0f));
  features.albedo = image::ImageF(w, 1, glm::vec4(albedo, albedo, albedo, 1.0f));
  features.normal = image::ImageF(w, 1);
  features.depth = image::ImageF(w, 1, glm::vec4(1.0f));
  for (int x = 0; x < w; ++x) features.normal.at(x, 0) = glm::vec4(normals[std::size_t(x)], 1.0f);
  return features;
}

TEST(ChartRegions, UnshadowedRadianceMatchesClosedForms) {
  const std::vector<glm::vec3> normals = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, glm::normalize(glm::vec3(1, 2, -3))};
  const ref::PixelFeatures features = features_with_normals(normals, 0.5f);
  // Constant radiance 1 (L_00 = sqrt(4π)): E = π for every normal, radiance = albedo = 0.5.
  sh::RgbSh constant;
  constant.order = 4;
  for (auto& c : constant.channels) c.assign(16, 0.0), c[0] = sh::kSqrtFourPi;
  const image::ImageF flat = unshadowed_radiance(features, constant);
  for (int x = 0; x < 4; ++x) EXPECT_NEAR(flat.at(x, 0).g, 0.5f, 1e-6f);
  // L(ω) = d · ω (band 1: L_1m = 4π/3 y_1m(d), the addition theorem): E(N) = 2π/3 N · d
  // (∫ over N's hemisphere of (d · ω)(N · ω)), radiance = 0.5 / π · E = N · d / 3.
  const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, 0.8, 0.4));
  std::vector<double> basis(4);
  sh::evaluate_basis(2, d, basis);
  sh::RgbSh linear;
  linear.order = 2;
  for (auto& c : linear.channels) {
    c.assign(4, 0.0);
    for (int i = 1; i < 4; ++i) c[std::size_t(i)] = 4.0 * std::numbers::pi / 3.0 * basis[std::size_t(i)];
  }
  const image::ImageF lit = unshadowed_radiance(features, linear);
  for (int x = 0; x < 4; ++x)
    EXPECT_NEAR(lit.at(x, 0).r, glm::dot(glm::dvec3(normals[std::size_t(x)]), d) / 3.0, 1e-6) << "normal " << x;
}

TEST(ChartRegions, ShadowRegionIsDirectBelowUnshadowedByTheFraction) {
  // Unshadowed 1; direct 0.9 (shadow at 5 %), 0.97 (not), 1.0 (not), 0.5 outside `where`, and a
  // pixel whose unshadowed light is 0 (never shadow).
  image::ImageF direct(5, 1), open(5, 1, glm::vec4(1.0f));
  const float values[5] = {0.9f, 0.97f, 1.0f, 0.5f, 0.0f};
  for (int x = 0; x < 5; ++x) direct.at(x, 0) = glm::vec4(values[x]);
  open.at(4, 0) = glm::vec4(0.0f);
  const ref::ReceiverMask where = ref::mask_where(5, 1, [](int x, int) { return x != 3; });
  EXPECT_EQ(to_rows(shadow_region(direct, open, where, 0.05)), std::vector<std::string>{"#...."});
  EXPECT_EQ(to_rows(shadow_region(direct, open, where, 0.02)), std::vector<std::string>{"##..."});
}

TEST(ChartRegions, ScoresOnlyTheRegionsAPixelBelongsToAndCountsBounds) {
  // 6 receivers, reference 1 everywhere, upper bound 1. Test: pixel 0 = 2 (error (2−1)²/(1+0.01)
  // in the character and edge regions), pixel 1 = −0.5 (negative; in the shadow region), pixel 2
  // = NaN (non-finite), pixel 3 = 1.01 (above 1 + 1/255), pixels 4, 5 exact (contact region).
  ChartRegions regions;
  regions.receivers = ref::mask_where(6, 1, [](int, int) { return true; });
  regions.upper_bound = image::ImageF(6, 1, glm::vec4(1.0f));
  auto only = [](std::initializer_list<int> pixels) {
    return ref::mask_where(6, 1, [pixels](int x, int) { return std::find(pixels.begin(), pixels.end(), x) != pixels.end(); });
  };
  regions.masks[std::size_t(ChartRegion::shadow)] = only({1});
  regions.masks[std::size_t(ChartRegion::edge)] = only({0, 5});
  regions.masks[std::size_t(ChartRegion::thin)] = only({});
  regions.masks[std::size_t(ChartRegion::character)] = only({0});
  regions.masks[std::size_t(ChartRegion::contact)] = only({4, 5});
  const image::ImageF reference(6, 1, glm::vec4(1.0f));
  image::ImageF test = reference;
  test.at(0, 0) = glm::vec4(2.0f);
  test.at(1, 0) = glm::vec4(-0.5f);
  test.at(2, 0) = glm::vec4(std::numeric_limits<float>::quiet_NaN());
  test.at(3, 0) = glm::vec4(1.01f);
  // NaN cannot be scored by relative_mse's mean; score the finite pixels' regions on a copy.
  image::ImageF finite = test;
  finite.at(2, 0) = glm::vec4(1.0f);
  auto scored = score_regions(finite, reference, regions);
  ASSERT_TRUE(scored) << scored.message();
  const double e0 = 1.0 / 1.01, e1 = 1.5 * 1.5 / 1.01;
  EXPECT_NEAR(scored->relative_mse(ChartRegion::character), e0, 1e-6);
  EXPECT_NEAR(scored->relative_mse(ChartRegion::edge), e0 / 2.0, 1e-6);
  EXPECT_NEAR(scored->relative_mse(ChartRegion::shadow), e1, 1e-6);
  EXPECT_NEAR(scored->relative_mse(ChartRegion::contact), 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(scored->relative_mse(ChartRegion::thin)));
  EXPECT_EQ(scored->negative, 1.0);
  EXPECT_EQ(scored->above_unshadowed, 2.0);  // 2 and 1.01
  EXPECT_EQ(scored->non_finite, 0.0);
  // The NaN pixel is counted by the bounds.
  regions.masks[std::size_t(ChartRegion::edge)] = only({0});
  auto with_nan = score_regions(test, reference, regions);
  ASSERT_TRUE(with_nan) << with_nan.message();
  EXPECT_EQ(with_nan->non_finite, 1.0);
  EXPECT_EQ(with_nan->negative, 1.0);
}

ChartRow region_row(const std::string& scene, double shadow_error, double shadow_pixels) {
  ChartRow row;
  row.scene = scene;
  row.method = "proxy";
  row.sh_order = 4;
  row.receiver_scale = 4;
  row.upsampling = "bilateral";
  row.indirect = "averaged";
  RegionErrors frame;
  frame.measured = true;
  frame.error_sum[std::size_t(ChartRegion::shadow)] = shadow_error * shadow_pixels;
  frame.pixels[std::size_t(ChartRegion::shadow)] = shadow_pixels;
  frame.pixels[std::size_t(ChartRegion::character)] = 10.0;
  frame.negative = 2.0;
  row.regions.add(frame, 0.5);  // two frames, both alike
  row.regions.add(frame, 0.5);
  return row;
}

TEST(ChartRegions, RowsAverageRegionsOverFramesAndNonEmptyScenes) {
  // Scene a: shadow relMSE 0.2 on 100 px; scene b: no shadow pixels. The mean over scenes is
  // a's 0.2 (b has nothing to average), with 50 px per frame on the mean; character has pixels
  // but no error: 0; negative pixels average to 2 per frame.
  std::vector<ChartRow> rows = {region_row("a", 0.2, 100.0), region_row("b", 0.0, 0.0)};
  EXPECT_NEAR(rows[0].regions.relative_mse(ChartRegion::shadow), 0.2, 1e-12);
  EXPECT_TRUE(std::isnan(rows[1].regions.relative_mse(ChartRegion::shadow)));
  const std::vector<ChartRow> means = mean_over_scenes(rows);
  ASSERT_EQ(means.size(), 1u);
  EXPECT_NEAR(means[0].regions.relative_mse(ChartRegion::shadow), 0.2, 1e-12);
  EXPECT_NEAR(means[0].regions.pixels[std::size_t(ChartRegion::shadow)], 50.0, 1e-12);
  EXPECT_NEAR(means[0].regions.relative_mse(ChartRegion::character), 0.0, 1e-12);
  EXPECT_NEAR(means[0].regions.negative, 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(means[0].regions.relative_mse(ChartRegion::thin)));
  // The CSV gains the region columns (empty where the region is), the JSON a "regions" object.
  const std::string csv = to_csv(rows);
  EXPECT_NE(csv.find(",shadow_relative_mse,shadow_pixels,edge_relative_mse"), std::string::npos);
  EXPECT_NE(csv.find(",default,shadow_relative_mse"), std::string::npos);
  EXPECT_NE(csv.find("\nb,proxy,proxy n4 k4 bilateral averaged,4,4,bilateral,averaged,0,0,0,0,0,0,0,0,0,0,,0,"), std::string::npos);
  EXPECT_NE(to_json(rows).find("\"regions\""), std::string::npos);
  EXPECT_NE(to_region_markdown(rows, "b").find("| n/a |"), std::string::npos);
  // Rows without regions: the CSV and JSON are as before --regions existed.
  rows[0].regions = rows[1].regions = RegionErrors{};
  EXPECT_EQ(to_csv(rows).substr(0, to_csv(rows).find('\n')),
            "scene,method,label,sh_order,receiver_scale,upsampling,indirect,samples,ms_per_frame,relative_mse,rmse,ssim,"
            "flip,character_relative_mse,character_luminance_ratio,pareto,default");
  EXPECT_EQ(to_json(rows).find("\"regions\""), std::string::npos);
}

}  // namespace
}  // namespace proxygi::study
