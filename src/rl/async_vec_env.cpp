// Asynchronous vector environment (see async_vec_env.h).
#include "rl/async_vec_env.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "rl/thread_pool.h"
#include "rl/vec_env.h"

namespace psxrl::rl {

namespace {

std::vector<std::vector<std::uint8_t>> buffers(const std::vector<Space>& spaces, size_t slots) {
  std::vector<std::vector<std::uint8_t>> b;
  for (const Space& s : spaces) b.emplace_back(s.bytes() * slots);
  return b;
}

}  // namespace

AsyncVecEnv::AsyncVecEnv(const EnvConfig& config, int num_envs, int batch_size, unsigned threads)
    : batch_size_(batch_size) {
  if (num_envs < 1) throw std::invalid_argument("an asynchronous vector environment needs at least one environment");
  if (batch_size < 1 || batch_size > num_envs)
    throw std::invalid_argument("batch_size must be between 1 and num_envs (" + std::to_string(num_envs) + "), got " +
                                std::to_string(batch_size));
  if (threads == 0) threads = 1;
  envs_.resize(static_cast<size_t>(num_envs));
  {
    ThreadPool boot(threads);  // booting is the slow part of construction
    boot.parallel_for(envs_.size(), [&](size_t i) { envs_[i] = std::make_unique<Env>(config); });
  }
  outcomes_.resize(envs_.size());
  for (Outcome& o : outcomes_) o.final_obs = buffers(observation_spaces(), 1);
  slots_.assign(envs_.size(), Slot::kHeld);
  episodes_.assign(envs_.size(), 0);
  batch_.observations = buffers(observation_spaces(), static_cast<size_t>(batch_size));
  batch_.final_observations = buffers(observation_spaces(), static_cast<size_t>(batch_size));
  for (unsigned i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

AsyncVecEnv::~AsyncVecEnv() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  work_ready_.notify_all();
  for (auto& w : workers_) w.join();
}

void AsyncVecEnv::copy_observation(const Observation& obs, size_t slot, std::vector<std::vector<std::uint8_t>>& into) {
  for (size_t p = 0; p < obs.size(); ++p) {
    const size_t bytes = obs[p].space->bytes();
    std::memcpy(into[p].data() + slot * bytes, obs[p].data, bytes);
  }
}

// One task, on a worker: the environment is this thread's alone until it is marked ready.
void AsyncVecEnv::run(const Task& task) {
  Env& env = *envs_[static_cast<size_t>(task.env)];
  Outcome& out = outcomes_[static_cast<size_t>(task.env)];
  std::uint64_t& episode = episodes_[static_cast<size_t>(task.env)];
  out.error = nullptr;
  try {
    if (task.action < 0) {
      out.result = StepResult{};
      episode = 0;
      env.reset(level_, episode_seed(seed_, task.env, episode), &out.result.info);
      return;
    }
    out.result = env.step(task.action);
    if (out.result.terminated || out.result.truncated) {
      copy_observation(env.observation(), 0, out.final_obs);
      env.reset(level_, episode_seed(seed_, task.env, ++episode));
    }
  } catch (...) {
    out.error = std::current_exception();
  }
}

void AsyncVecEnv::work() {
  std::unique_lock lock(mutex_);
  for (;;) {
    work_ready_.wait(lock, [&] { return stop_ || !tasks_.empty(); });
    if (tasks_.empty()) return;  // stopping, and nothing left in flight
    const Task task = tasks_.front();
    tasks_.pop_front();
    ++running_;
    lock.unlock();
    run(task);
    lock.lock();
    --running_;
    slots_[static_cast<size_t>(task.env)] = Slot::kReady;
    ready_.push_back(task.env);
    env_ready_.notify_all();
  }
}

void AsyncVecEnv::wait_idle(std::unique_lock<std::mutex>& lock) {
  env_ready_.wait(lock, [&] { return tasks_.empty() && running_ == 0; });
}

void AsyncVecEnv::reset(int level, std::uint64_t seed) {
  psx::ThreadOwner::Use use(owner_);
  std::unique_lock lock(mutex_);
  wait_idle(lock);
  level_ = level;
  seed_ = seed;
  ready_.clear();
  for (int i = 0; i < size(); ++i) {
    slots_[static_cast<size_t>(i)] = Slot::kQueued;
    tasks_.push_back({i, -1});
  }
  work_ready_.notify_all();
}

void AsyncVecEnv::send(const std::vector<int>& actions, const std::vector<int>& env_ids) {
  psx::ThreadOwner::Use use(owner_);
  if (actions.size() != env_ids.size())
    throw std::invalid_argument("send: " + std::to_string(actions.size()) + " actions for " +
                                std::to_string(env_ids.size()) + " environment ids");
  std::lock_guard lock(mutex_);
  std::vector<bool> listed(envs_.size());
  for (size_t k = 0; k < env_ids.size(); ++k) {
    const int id = env_ids[k];
    if (id < 0 || id >= size())
      throw std::invalid_argument("send: environment id " + std::to_string(id) + " is outside 0.." +
                                  std::to_string(size() - 1));
    if (slots_[static_cast<size_t>(id)] != Slot::kHeld || listed[static_cast<size_t>(id)])
      throw std::invalid_argument("send: environment " + std::to_string(id) +
                                  " is already in flight (send it again only after recv() returns it)");
    listed[static_cast<size_t>(id)] = true;
    if (actions[k] < 0 || actions[k] >= action_count())
      throw std::invalid_argument("send: action " + std::to_string(actions[k]) + " is outside 0.." +
                                  std::to_string(action_count() - 1));
  }
  // Nothing is queued unless every move is valid.
  for (size_t k = 0; k < env_ids.size(); ++k) {
    slots_[static_cast<size_t>(env_ids[k])] = Slot::kQueued;
    tasks_.push_back({env_ids[k], actions[k]});
  }
  work_ready_.notify_all();
}

const AsyncBatch& AsyncVecEnv::recv() {
  psx::ThreadOwner::Use use(owner_);
  std::unique_lock lock(mutex_);
  int in_flight = 0;
  for (Slot s : slots_) in_flight += s != Slot::kHeld;
  if (in_flight < batch_size_)
    throw std::logic_error("recv: only " + std::to_string(in_flight) + " environments are in flight, fewer than the batch size " +
                           std::to_string(batch_size_) + " (send() them first)");
  env_ready_.wait(lock, [&] { return static_cast<int>(ready_.size()) >= batch_size_; });
  batch_.env_ids.assign(ready_.begin(), ready_.begin() + batch_size_);
  ready_.erase(ready_.begin(), ready_.begin() + batch_size_);
  for (int id : batch_.env_ids) slots_[static_cast<size_t>(id)] = Slot::kHeld;
  lock.unlock();

  // The returned environments are held by the caller now, so no worker touches them.
  const size_t n = static_cast<size_t>(batch_size_);
  batch_.rewards.resize(n);
  batch_.terminated.resize(n);
  batch_.truncated.resize(n);
  batch_.infos.resize(n);
  for (size_t k = 0; k < n; ++k) {
    const size_t id = static_cast<size_t>(batch_.env_ids[k]);
    const Outcome& out = outcomes_[id];
    if (out.error) std::rethrow_exception(out.error);
    batch_.rewards[k] = out.result.reward;
    batch_.terminated[k] = out.result.terminated;
    batch_.truncated[k] = out.result.truncated;
    batch_.infos[k] = out.result.info;
    copy_observation(envs_[id]->observation(), k, batch_.observations);
    if (out.result.terminated || out.result.truncated)
      for (size_t p = 0; p < out.final_obs.size(); ++p) {
        const size_t bytes = out.final_obs[p].size();
        std::memcpy(batch_.final_observations[p].data() + k * bytes, out.final_obs[p].data(), bytes);
      }
  }
  return batch_;
}

}  // namespace psxrl::rl
