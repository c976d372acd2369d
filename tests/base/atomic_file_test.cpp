#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "base/atomic_file.h"

namespace proxygi {
namespace {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto directory = std::filesystem::path(PROXYGI_TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(AtomicFile, WritesAndReplacesWholeFile) {
  const auto path = fresh_directory("atomic_write") / "a.txt";
  ASSERT_TRUE(write_file_atomically(path, std::string_view("first")).ok());
  ASSERT_TRUE(write_file_atomically(path, std::string_view("second")).ok());
  EXPECT_EQ(read_text(path), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(path.parent_path()), {}), 1);
}

TEST(AtomicFile, FailedWriterLeavesNothing) {
  const auto directory = fresh_directory("atomic_fail");
  const auto path = directory / "b.txt";
  const Status status = write_via_temporary(path, [](const std::filesystem::path& temporary) -> Status {
    std::ofstream(temporary) << "partial";
    return make_error("writer gave up");
  });
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), "writer gave up");
  EXPECT_TRUE(std::filesystem::is_empty(directory));
}

// A writer's message naming the temporary (a library that opened it) names the user's path.
TEST(AtomicFile, WriterMessagesNameTheUserPath) {
  const auto path = fresh_directory("atomic_name") / "e.txt";
  const Status status = write_via_temporary(path, [](const std::filesystem::path& temporary) -> Status {
    return make_error("cannot open " + temporary.string() + " (" + temporary.filename().string() + ")");
  });
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.message(), "cannot open " + path.string() + " (" + path.string() + ")");
  EXPECT_EQ(status.message().find(".tmp-"), std::string::npos) << status.message();
}

TEST(AtomicFile, ErrorNamesMissingFolder) {
  const auto path = fresh_directory("atomic_missing") / "no" / "such" / "c.txt";
  const Status status = write_file_atomically(path, std::string_view("x"));
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.message().find(path.string() + ": cannot create it in its folder"), std::string::npos) << status.message();
  EXPECT_EQ(status.message().find(".tmp-"), std::string::npos) << status.message();
}

TEST(ReadFile, RefusesOversizeAndDirectories) {
  const auto directory = fresh_directory("read_file");
  const auto path = directory / "d.bin";
  ASSERT_TRUE(write_file_atomically(path, std::string_view("0123456789")).ok());
  auto small = read_file(path, 10);
  ASSERT_TRUE(small.ok());
  EXPECT_EQ(small->size(), 10u);
  auto big = read_file(path, 9);
  ASSERT_FALSE(big.ok());
  EXPECT_NE(big.message().find("more than the limit of 9 bytes"), std::string::npos) << big.message();
  EXPECT_FALSE(read_file(directory, 100).ok());
}

}  // namespace
}  // namespace proxygi
