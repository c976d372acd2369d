#pragma once
// Shared fixture for tests that touch Vulkan: one Context per test binary with the validation
// layer forced on. Every test ends by asserting that no validation message appeared during it.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/context.h"
#include "gpu/transfer.h"

namespace proxygi::gpu::testing {

class GpuTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto created = Context::create({.device_request = "", .validation = Validation::on});
    if (!created) {
      creation_error() = created.message();
      return;
    }
    shared_context() = std::move(*created);
  }
  static void TearDownTestSuite() { shared_context().reset(); }

  void SetUp() override {
    ASSERT_TRUE(shared_context()) << "no Vulkan context: " << creation_error();
    ASSERT_TRUE(shared_context()->validation_enabled());
    messages_before_ = shared_context()->validation_message_count();
  }
  void TearDown() override {
    if (!shared_context()) return;
    ASSERT_EQ(shared_context()->validation_message_count(), messages_before_)
        << "validation messages during the test (see stderr)";
  }

  Context& context() { return *shared_context(); }

 private:
  static std::unique_ptr<Context>& shared_context() {
    static std::unique_ptr<Context> context;
    return context;
  }
  static std::string& creation_error() {
    static std::string error;
    return error;
  }
  std::size_t messages_before_ = 0;
};

// The first `count` vec4s of a device buffer (zeros, and a test failure, when the read fails).
inline std::vector<glm::vec4> read_vec4s(Context& context, const Buffer& buffer, std::size_t count) {
  auto bytes = readback(context, buffer);
  EXPECT_TRUE(bytes.ok());
  std::vector<glm::vec4> values(count);
  if (bytes.ok()) std::memcpy(values.data(), bytes->data(), count * sizeof(glm::vec4));
  return values;
}

}  // namespace proxygi::gpu::testing
