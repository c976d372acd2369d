// The PRT cache: a second load reads the file; a corrupt file or changed settings recompute.
#include "prt/transfer_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "prt_scenes.h"

namespace proxygi::prt {
namespace {

std::filesystem::path fresh_dir(const char* name) {
  const std::filesystem::path dir = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / "prt" / name;
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(PrtCache, SecondLoadReadsTheFileBitForBit) {
  const StaticReceivers r = test::wall_corner(0.4f);
  const TransferSettings settings{.order = 3, .directions = 64, .bounces = 1};
  const std::filesystem::path dir = fresh_dir("roundtrip");
  auto first = load_or_compute_transfer(r, settings, dir);
  ASSERT_TRUE(first.ok()) << first.message();
  EXPECT_FALSE(first->from_cache);
  EXPECT_TRUE(std::filesystem::exists(first->file));
  auto second = load_or_compute_transfer(r, settings, dir);
  ASSERT_TRUE(second.ok()) << second.message();
  EXPECT_TRUE(second->from_cache);
  ASSERT_EQ(second->transfer.surfaces.size(), r.surfaces.size());
  for (std::size_t s = 0; s < r.surfaces.size(); ++s) {
    EXPECT_EQ(second->transfer.surfaces[s].shadowed, first->transfer.surfaces[s].shadowed);
    EXPECT_EQ(second->transfer.surfaces[s].interreflected, first->transfer.surfaces[s].interreflected);
  }
  // No temporary is left next to it.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(PrtCache, CorruptFileIsRecomputed) {
  const StaticReceivers r = test::wall_corner(0.4f);
  const TransferSettings settings{.order = 3, .directions = 64, .bounces = 1};
  const std::filesystem::path dir = fresh_dir("corrupt");
  auto first = load_or_compute_transfer(r, settings, dir);
  ASSERT_TRUE(first.ok()) << first.message();
  {  // flip one byte in the middle of the payload
    std::fstream f(first->file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(std::filesystem::file_size(first->file) / 2));
    f.put('\x5a');
  }
  const std::uint64_t key = transfer_key(r, settings);
  auto direct = read_transfer_file(first->file, key, r);
  ASSERT_FALSE(direct.ok());
  EXPECT_NE(direct.message().find("checksum mismatch"), std::string::npos) << direct.message();
  auto again = load_or_compute_transfer(r, settings, dir);
  ASSERT_TRUE(again.ok()) << again.message();
  EXPECT_FALSE(again->from_cache);
  EXPECT_EQ(again->transfer.surfaces[0].interreflected, first->transfer.surfaces[0].interreflected);
  EXPECT_TRUE(read_transfer_file(again->file, key, r).ok());  // rewritten intact
}

TEST(PrtCache, KeyChangesWithGeometryAndSettings) {
  const StaticReceivers r = test::wall_corner(0.4f);
  const TransferSettings settings{.order = 3, .directions = 64, .bounces = 1};
  const std::uint64_t key = transfer_key(r, settings);
  EXPECT_EQ(key, transfer_key(test::wall_corner(0.4f), settings));
  EXPECT_NE(key, transfer_key(r, {.order = 4, .directions = 64, .bounces = 1}));
  EXPECT_NE(key, transfer_key(r, {.order = 3, .directions = 64, .bounces = 2}));
  EXPECT_NE(key, transfer_key(test::wall_corner(0.4f, glm::vec3(0.5f)), settings));
  StaticReceivers moved = r;
  moved.surfaces[1].positions[0].x += 0.01f;
  EXPECT_NE(key, transfer_key(moved, settings));
}

}  // namespace
}  // namespace proxygi::prt
