// Fixed thread pool (see thread_pool.h).
#include "rl/thread_pool.h"

namespace psxrl::rl {

ThreadPool::ThreadPool(unsigned threads) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadPool::run_items(std::unique_lock<std::mutex>& lock) {
  while (fn_ && next_ < count_) {
    size_t i = next_++;
    const auto* fn = fn_;
    lock.unlock();
    std::exception_ptr err;
    try {
      (*fn)(i);
    } catch (...) {
      err = std::current_exception();
    }
    lock.lock();
    if (err && !error_) error_ = err;
    if (++finished_ == count_) done_.notify_all();
  }
}

void ThreadPool::work() {
  unsigned seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    run_items(lock);
  }
}

void ThreadPool::parallel_for(size_t n, const std::function<void(size_t)>& fn) {
  if (n == 0) return;
  std::unique_lock lock(mutex_);
  fn_ = &fn;
  next_ = 0;
  count_ = n;
  finished_ = 0;
  error_ = nullptr;
  ++generation_;
  wake_.notify_all();
  run_items(lock);
  done_.wait(lock, [&] { return finished_ == count_; });
  fn_ = nullptr;
  if (error_) std::rethrow_exception(error_);
}

}  // namespace psxrl::rl
