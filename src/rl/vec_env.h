// N environments stepped together on a thread pool (EnvPool's design): a batched step with
// automatic reset, observations gathered into one contiguous array per observation part
// ([num_envs, ...shape]). Each environment has its own console and Lua state and is stepped by
// one thread at a time, so the results equal N single environments driven the same way, bit for
// bit, whatever the thread count: environment i's k-th episode starts with
// reset(level, episode_seed(seed, i, k)). One calling thread at a time: reset() or step() from a
// second thread while one runs throws std::runtime_error (util/thread_owner.h).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "util/thread_owner.h"
#include "rl/env.h"
#include "rl/thread_pool.h"

namespace psxrl::rl {

std::uint64_t episode_seed(std::uint64_t seed, int env_index, std::uint64_t episode);

struct VecStep {
  std::vector<double> rewards;
  std::vector<std::uint8_t> terminated, truncated;
  std::vector<StepInfo> infos;  // the finished episode's info where it ended
};

class VecEnv {
 public:
  VecEnv(const EnvConfig& config, int num_envs, unsigned threads);

  int size() const { return static_cast<int>(envs_.size()); }
  unsigned threads() const { return pool_.size(); }
  const std::vector<Space>& observation_spaces() const { return envs_[0]->observation_spaces(); }
  int action_count() const { return envs_[0]->action_count(); }
  Env& env(int i) { return *envs_[static_cast<size_t>(i)]; }

  // Starts every environment on `level`; environment i uses episode_seed(seed, i, 0).
  void reset(int level, std::uint64_t seed);
  // One move in every environment. An environment whose episode ends is reset at once (its
  // next episode's seed as above); its last observation is kept in final_batch().
  const VecStep& step(const std::vector<int>& actions);

  // One byte buffer per observation part, num_envs slots of the part's size each.
  const std::vector<std::vector<std::uint8_t>>& batch() const { return batch_; }
  const std::vector<std::vector<std::uint8_t>>& final_batch() const { return final_; }

 private:
  void gather(size_t i, std::vector<std::vector<std::uint8_t>>& into);

  std::vector<std::unique_ptr<Env>> envs_;
  ThreadPool pool_;
  int level_ = 1;
  std::uint64_t seed_ = 0;
  std::vector<std::uint64_t> episodes_;
  std::vector<std::vector<std::uint8_t>> batch_, final_;
  VecStep result_;
  psx::ThreadOwner owner_{"VecEnv"};
};

}  // namespace psxrl::rl
