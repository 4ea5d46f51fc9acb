// The training loop (see trainer.h): K environments, each running its own episodes, stepped in
// parallel on the thread pool, while one agent acts, observes and learns for each in turn.
//
// Environment i's k-th episode (0-based) starts with reset(level, episode_seed(seed, i, k)) as
// in the vector environment, and is a greedy test when k + 1 is a multiple of test_every. Every
// move of every environment is one step of the same order: the agent picks the actions for
// environments 0..K-1, the environments step together, then for 0..K-1 in turn the agent
// observes the move and learns, and an episode that ended is recorded (so episodes are numbered
// in the order they end, ties by environment index). Environments whose episode ended start their
// next one together before the next move. With K = 1 this is the single-environment loop: reset,
// then act, step, observe, learn until the episode ends.
//
// With --start-states P, the state after every training move that did not end its episode is
// offered to a reservoir of kSavedStates saved states, and a training episode starts from one of
// them, drawn uniformly, with probability P; all these draws come from the trainer's own
// generator, in the loop's fixed order, so runs stay deterministic.
#include <algorithm>
#include <chrono>

#include "rl/agents/trainer.h"
#include "rl/vec_env.h"

namespace psxrl::agents {

// Whether the slot's next episode is a test and where it starts; on the calling thread, as it
// draws from the trainer's generator. Test episodes start at the run's start; held-out tests
// waiting after the last test come first.
void Trainer::plan_episode(size_t i) {
  Slot& s = slots_[i];
  s.heldout = 0;
  if (!pending_.empty()) {
    s.heldout = pending_.front();
    pending_.erase(pending_.begin());
    s.test = true;
    s.from = -1;
    return;
  }
  s.test = (s.episodes + 1) % static_cast<std::uint64_t>(config_.test_every) == 0;
  s.from = -1;
  if (!s.test && config_.start_states > 0 && !saved_.empty() && start_rng_.uniform() < config_.start_states)
    s.from = static_cast<std::ptrdiff_t>(start_rng_.below(saved_.size()));
}

// Starts the planned episode; slots start in parallel.
// Held-out tests draw their seeds from a sequence of their own (environment index -2), so the
// training and test episodes' seeds are those of a run without them.
void Trainer::begin_episode(size_t i) {
  Slot& s = slots_[i];
  std::uint64_t seed = s.heldout ? rl::episode_seed(config_.seed, -2, heldout_played_++)
                                 : rl::episode_seed(config_.seed, static_cast<int>(i), s.episodes++);
  s.start = std::chrono::steady_clock::now();
  // An episode's frames are all the console ran for it, its level's start (and walk) included.
  rl::StepInfo info;
  if (s.from >= 0) s.state = features(s.env->reset_to(saved_[static_cast<size_t>(s.from)], seed, &info));
  else if (s.heldout) s.state = features(begin_at(*s.env, config_.level, test_starts_[s.heldout - 1], seed, &info));
  else s.state = features(begin_at(*s.env, config_.level, start_, seed, &info));
  s.frames = info.game_frames;
}

// Reservoir sampling: the n-th state offered replaces a random kept one with probability
// kSavedStates / n, so the kept states are a uniform sample of all offered.
void Trainer::offer_state(Slot& s) {
  ++offered_;
  if (saved_.size() < kSavedStates) {
    saved_.push_back(s.env->snapshot());
    return;
  }
  std::uint64_t j = start_rng_.below(offered_);
  if (j < kSavedStates) saved_[j] = s.env->snapshot();
}

// The agent's part of one environment's move; true when the move ended its episode.
bool Trainer::learn_from_move(Slot& s, const Progress& progress) {
  const rl::StepResult& r = s.result;
  if (!s.test) {
    agent_->observe({s.state, s.action, r.reward, s.next, r.terminated});
    agent_->learn();
  }
  bool over = r.terminated || r.truncated;
  if (!s.test && !over && config_.start_states > 0) offer_state(s);
  s.state = std::move(s.next);
  s.frames += r.info.game_frames;
  ++session_moves_;
  if (progress) progress(status(counted_ + 1, false));
  return over;
}

// Records the slot's finished episode; true when the run is over.
bool Trainer::end_episode(Slot& s, const Progress& progress) {
  const rl::StepResult& r = s.result;
  EpisodeRecord rec;
  rec.episode = s.heldout ? last_test_ : counted_ + 1;
  rec.test = s.test;
  rec.score = r.info.score;
  rec.reward = r.info.episode_reward;
  rec.moves = r.info.moves;
  rec.frames = s.frames;
  rec.outcome = r.info.outcome.empty() ? "truncated" : r.info.outcome;
  rec.epsilon = agent_->epsilon();
  rec.loss = agent_->last_loss();
  rec.total_moves = agent_->moves();
  rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - s.start).count();
  rec.saved_start = s.from >= 0;
  rec.heldout = s.heldout;
  records_.push_back(rec);
  if (!rec.heldout) ++counted_;
  if (rec.test && !rec.heldout) {
    last_test_ = rec.episode;
    for (size_t k = 1; k <= test_starts_.size(); ++k) pending_.push_back(static_cast<int>(k));
  }
  ++session_episodes_;
  append_metrics(rec);
  bool stop = rec.test && !rec.heldout && config_.stop_score && rec.score >= *config_.stop_score;
  stopping_ = stopping_ || stop || counted_ >= config_.episodes;
  bool over = stopping_ && pending_.empty();
  // The curve after each test and at the end: drawn after every episode it took 7% of a short
  // DQN run's CPU time (docs/results.md, "Speed of learning").
  save(rec.test || over);
  if (progress) progress(status(rec.episode, true));
  return over;
}

void Trainer::run(const Progress& progress) {
  run_start_ = std::chrono::steady_clock::now();
  if (counted_ >= config_.episodes) return;
  size_t k = slots_.size();
  for (size_t i = 0; i < k; ++i) plan_episode(i);
  pool_->parallel_for(k, [&](size_t i) { begin_episode(i); });
  for (;;) {
    for (Slot& s : slots_) s.action = agent_->act(s.state, s.test);
    pool_->parallel_for(k, [&](size_t i) {
      Slot& s = slots_[i];
      s.result = s.env->step(s.action);
      s.next = features(s.env->observation());
    });
    std::vector<size_t> ended;
    for (size_t i = 0; i < k; ++i) {
      if (!learn_from_move(slots_[i], progress)) continue;
      if (end_episode(slots_[i], progress)) return;
      ended.push_back(i);
    }
    for (size_t i : ended) plan_episode(i);
    pool_->parallel_for(ended.size(), [&](size_t j) { begin_episode(ended[j]); });
  }
}

std::optional<std::uint64_t> Trainer::first_win() const {
  for (const EpisodeRecord& r : records_)
    if (r.test && !r.heldout && r.outcome == "win") return r.episode;
  return std::nullopt;
}

TrainStatus Trainer::status(std::uint64_t episode, bool episode_end) const {
  TrainStatus s{};
  s.episode = episode;
  s.episode_end = episode_end;
  s.episodes = config_.episodes;
  s.moves = agent_->moves();
  for (const EpisodeRecord& r : records_) {
    if (r.heldout) continue;
    if (r.test) {
      s.last_test = r.score;
      s.best_test = std::max(s.best_test.value_or(r.score), r.score);
    } else {
      s.last_train = r.score;
    }
  }
  s.epsilon = agent_->epsilon();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start_).count();
  s.moves_per_second = seconds > 0 ? static_cast<double>(session_moves_) / seconds : 0;
  double per_episode = seconds / std::max<double>(1.0, static_cast<double>(session_episodes_));
  s.eta_seconds = per_episode * static_cast<double>(config_.episodes - std::min(config_.episodes, counted_));
  return s;
}

}  // namespace psxrl::agents
