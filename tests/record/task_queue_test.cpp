// The record encoder queue (run/task_queue.h): every pushed task runs exactly once, at most
// `capacity` wait, the first error stops further pushes and is reported by wait().
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "run/task_queue.h"

namespace proxygi::run {
namespace {

TEST(TaskQueue, RunsEveryTaskOnceWithBoundedWaiting) {
  std::atomic<int> ran{0}, waiting_peak{0}, in_queue{0};
  {
    TaskQueue queue(3, 2);
    for (int i = 0; i < 100; ++i) {
      ++in_queue;
      waiting_peak = std::max(waiting_peak.load(), in_queue.load());
      ASSERT_TRUE(queue.push([&] {
        --in_queue;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
        ++ran;
        return Status{};
      }).ok());
    }
    EXPECT_TRUE(queue.wait().ok());
    EXPECT_EQ(ran.load(), 100);
  }
  EXPECT_LE(waiting_peak.load(), 2 + 3 + 1);  // queued + running + the one being pushed
}

TEST(TaskQueue, FirstErrorStopsPushesAndIsReported) {
  TaskQueue queue(2, 4);
  ASSERT_TRUE(queue.push([] { return Status(make_error("disk full: frame_00003.png")); }).ok());
  EXPECT_EQ(queue.wait().message(), "disk full: frame_00003.png");
  EXPECT_FALSE(queue.push([] { return Status{}; }).ok());
}

TEST(TaskQueue, DestructorFinishesPushedTasks) {
  std::atomic<int> ran{0};
  {
    TaskQueue queue(1, 8);
    for (int i = 0; i < 8; ++i)
      ASSERT_TRUE(queue.push([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++ran;
        return Status{};
      }).ok());
  }
  EXPECT_EQ(ran.load(), 8);
}

}  // namespace
}  // namespace proxygi::run
