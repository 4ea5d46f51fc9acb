// A small fixed pool of worker threads for stepping many environments at once (EnvPool's
// approach): parallel_for hands out indices 0..n-1 and returns when all are done. Work items
// must be independent; which thread runs which item never changes a result.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace psxrl::rl {

class ThreadPool {
 public:
  explicit ThreadPool(unsigned threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }
  // Runs fn(i) for i in [0, n) on the workers and the calling thread; rethrows the first
  // exception any item threw, after every item has finished.
  void parallel_for(size_t n, const std::function<void(size_t)>& fn);

 private:
  void work();
  void run_items(std::unique_lock<std::mutex>& lock);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(size_t)>* fn_ = nullptr;
  size_t next_ = 0, count_ = 0, finished_ = 0;
  unsigned generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

}  // namespace psxrl::rl
