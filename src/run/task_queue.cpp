#include "run/task_queue.h"

#include <algorithm>

namespace proxygi::run {

TaskQueue::TaskQueue(std::size_t workers, std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {
  for (std::size_t i = 0; i < std::max<std::size_t>(workers, 1); ++i) threads_.emplace_back([this] { work(); });
}

TaskQueue::~TaskQueue() {
  (void)wait();
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

Status TaskQueue::push(std::function<Status()> task) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return tasks_.size() < capacity_ || !first_error_; });
  if (!first_error_) return first_error_;
  tasks_.push_back(std::move(task));
  changed_.notify_all();
  return {};
}

Status TaskQueue::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return tasks_.empty() && running_ == 0; });
  return first_error_;
}

void TaskQueue::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !tasks_.empty(); });
    if (tasks_.empty()) return;  // stopping, nothing left
    std::function<Status()> task = std::move(tasks_.front());
    tasks_.pop_front();
    ++running_;
    changed_.notify_all();
    lock.unlock();
    Status done = task();
    lock.lock();
    --running_;
    if (!done && first_error_) first_error_ = done;
    changed_.notify_all();
  }
}

std::size_t default_encoder_threads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores > 1 ? cores - 1 : 1;
}

}  // namespace proxygi::run
