// Vector environment (see vec_env.h).
#include "rl/vec_env.h"

#include <cstring>
#include <stdexcept>

namespace psxrl::rl {

std::uint64_t episode_seed(std::uint64_t seed, int env_index, std::uint64_t episode) {
  // splitmix64's finaliser over a mix of the three; distinct inputs give unrelated seeds.
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (static_cast<std::uint64_t>(env_index) + 1) +
                    0xD1B54A32D192ED03ull * episode;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

VecEnv::VecEnv(const EnvConfig& config, int num_envs, unsigned threads) : pool_(threads ? threads : 1) {
  if (num_envs < 1) throw std::invalid_argument("a vector environment needs at least one environment");
  envs_.resize(static_cast<size_t>(num_envs));
  // Booting is the slow part of construction: do it in parallel too.
  pool_.parallel_for(envs_.size(), [&](size_t i) { envs_[i] = std::make_unique<Env>(config); });
  for (const auto& s : observation_spaces()) {
    batch_.emplace_back(s.bytes() * envs_.size());
    final_.emplace_back(s.bytes() * envs_.size());
  }
  episodes_.assign(envs_.size(), 0);
  result_.rewards.resize(envs_.size());
  result_.terminated.resize(envs_.size());
  result_.truncated.resize(envs_.size());
  result_.infos.resize(envs_.size());
}

void VecEnv::gather(size_t i, std::vector<std::vector<std::uint8_t>>& into) {
  const Observation& obs = envs_[i]->observation();
  for (size_t p = 0; p < obs.size(); ++p) {
    size_t bytes = obs[p].space->bytes();
    std::memcpy(into[p].data() + i * bytes, obs[p].data, bytes);
  }
}

void VecEnv::reset(int level, std::uint64_t seed) {
  psx::ThreadOwner::Use use(owner_);
  level_ = level;
  seed_ = seed;
  episodes_.assign(envs_.size(), 0);
  pool_.parallel_for(envs_.size(), [&](size_t i) {
    envs_[i]->reset(level, episode_seed(seed, static_cast<int>(i), 0));
    gather(i, batch_);
  });
}

const VecStep& VecEnv::step(const std::vector<int>& actions) {
  psx::ThreadOwner::Use use(owner_);
  if (actions.size() != envs_.size())
    throw std::invalid_argument("step: expected " + std::to_string(envs_.size()) + " actions, got " +
                                std::to_string(actions.size()));
  pool_.parallel_for(envs_.size(), [&](size_t i) {
    StepResult r = envs_[i]->step(actions[i]);
    result_.rewards[i] = r.reward;
    result_.terminated[i] = r.terminated;
    result_.truncated[i] = r.truncated;
    result_.infos[i] = r.info;
    if (r.terminated || r.truncated) {
      gather(i, final_);
      envs_[i]->reset(level_, episode_seed(seed_, static_cast<int>(i), ++episodes_[i]));
    }
    gather(i, batch_);
  });
  return result_;
}

}  // namespace psxrl::rl
