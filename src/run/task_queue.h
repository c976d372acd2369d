#pragma once
// A bounded queue of tasks run by worker threads, so `record` encodes and writes frame files
// while the GPU renders the next frames. Each task is independent (one frame's files), so the
// bytes written do not depend on the number of workers or their order.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "base/result.h"

namespace proxygi::run {

class TaskQueue {
 public:
  // `workers` threads (at least 1); push() blocks while `capacity` tasks wait (bounds memory).
  TaskQueue(std::size_t workers, std::size_t capacity);
  ~TaskQueue();  // finishes every pushed task
  TaskQueue(const TaskQueue&) = delete;
  TaskQueue& operator=(const TaskQueue&) = delete;

  // Queues a task; returns the first error any finished task reported so far (the task is then
  // not queued), so a caller stops producing work after a failure.
  Status push(std::function<Status()> task);
  // Waits until every pushed task finished; the first error, if any.
  Status wait();

 private:
  void work();
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<Status()>> tasks_;
  std::size_t capacity_ = 1;
  std::size_t running_ = 0;
  bool stopping_ = false;
  Status first_error_;
  std::vector<std::thread> threads_;
};

// Workers for file encoding on this machine: one per core beyond the one that drives the GPU.
std::size_t default_encoder_threads();

}  // namespace proxygi::run
