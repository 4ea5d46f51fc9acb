// N environments stepped asynchronously on worker threads (EnvPool's send/recv mode): recv()
// hands back the first batch_size environments to finish their reset or move, whichever they
// are, so no thread idles while the slowest move of a batch finishes (a Tumble move lasts 12 to
// 58 frames). Each environment's own trajectory stays deterministic: environment i's k-th
// episode starts with reset(level, episode_seed(seed, i, k)) exactly as in VecEnv, so the same
// actions sent to environment i give the same bits. Which environments share a batch depends on
// host timing, though, so an agent that mixes their experience is not reproducible run to run;
// the trainer uses the synchronous VecEnv for that reason. One calling thread at a time: reset(),
// send() or recv() from a second thread while one is inside throws std::runtime_error.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "util/thread_owner.h"
#include "rl/env.h"

namespace psxrl::rl {

struct AsyncBatch {
  std::vector<int> env_ids;  // batch_size environments, in the order they finished
  std::vector<double> rewards;
  std::vector<std::uint8_t> terminated, truncated;
  std::vector<StepInfo> infos;  // where an episode ended: that episode's last info
  // One byte buffer per observation part, batch_size slots in env_ids' order: the observation
  // to act on (after an autoreset, the new episode's first), and where an episode ended its last.
  std::vector<std::vector<std::uint8_t>> observations, final_observations;
};

class AsyncVecEnv {
 public:
  AsyncVecEnv(const EnvConfig& config, int num_envs, int batch_size, unsigned threads);
  ~AsyncVecEnv();  // lets moves in flight finish, then stops the workers
  AsyncVecEnv(const AsyncVecEnv&) = delete;
  AsyncVecEnv& operator=(const AsyncVecEnv&) = delete;

  int size() const { return static_cast<int>(envs_.size()); }
  int batch_size() const { return batch_size_; }
  unsigned threads() const { return static_cast<unsigned>(workers_.size()); }
  const std::vector<Space>& observation_spaces() const { return envs_[0]->observation_spaces(); }
  int action_count() const { return envs_[0]->action_count(); }
  // Environment i, for tools and tests (its on_frame, say): only while recv() has handed it back.
  Env& env(int i) { return *envs_[static_cast<size_t>(i)]; }

  // Waits for every move in flight, then starts every environment on `level` in the background
  // (environment i with episode_seed(seed, i, 0)); recv() returns them as they are ready.
  void reset(int level, std::uint64_t seed);
  // Queues one move for each listed environment; each must have come back from recv() and not
  // been sent since. An episode that ends is reset at once, as in VecEnv.
  void send(const std::vector<int>& actions, const std::vector<int>& env_ids);
  // Waits until batch_size environments are ready and returns them; rethrows an error a reset or
  // move threw. Throws if fewer than batch_size environments are in flight (it would never return).
  const AsyncBatch& recv();
  const AsyncBatch& last_batch() const { return batch_; }  // what the latest recv() returned

 private:
  enum class Slot : std::uint8_t { kHeld, kQueued, kReady };
  struct Task {
    int env;
    int action;  // -1: reset
  };
  struct Outcome {
    StepResult result;
    std::vector<std::vector<std::uint8_t>> final_obs;
    std::exception_ptr error;
  };

  void work();
  void run(const Task& task);
  void wait_idle(std::unique_lock<std::mutex>& lock);
  static void copy_observation(const Observation& obs, size_t slot, std::vector<std::vector<std::uint8_t>>& into);

  std::vector<std::unique_ptr<Env>> envs_;
  std::vector<Outcome> outcomes_;
  std::vector<Slot> slots_;
  std::vector<std::uint64_t> episodes_;
  int batch_size_;
  int level_ = 1;
  std::uint64_t seed_ = 0;

  std::mutex mutex_;
  std::condition_variable work_ready_, env_ready_;
  std::deque<Task> tasks_;
  std::deque<int> ready_;
  int running_ = 0;
  bool stop_ = false;
  std::vector<std::thread> workers_;

  AsyncBatch batch_;
  psx::ThreadOwner owner_{"AsyncVecEnv"};
};

}  // namespace psxrl::rl
