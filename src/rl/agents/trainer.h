// `psxrl train` without the command line: the seed's training loop (§4.2.1: nine ε-greedy
// training episodes, then one greedy test episode), experience from one or K environments
// stepped in parallel, per-episode metrics (CSV and JSON Lines) and a checkpoint after every
// episode, a learning-curve PNG after every test, and exact resumption (one environment).
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rl/agents/agent.h"
#include "rl/agents/checkpoint.h"
#include "rl/agents/start_position.h"
#include "rl/env.h"
#include "rl/thread_pool.h"

namespace psxrl::agents {

inline constexpr int kMaxEnvs = 64;
// Saved states kept for --start-states: a uniform sample (reservoir) of every training move's.
inline constexpr size_t kSavedStates = 32;

struct TrainConfig {
  rl::EnvConfig env;  // game, obs, gamma (also the agent's), max_moves, user files
  int level = 1;
  std::string agent = "dqn";
  AgentOptions options;
  std::uint64_t episodes = 1000;
  std::uint64_t seed = 0;
  int test_every = 10;  // every test_every-th episode of each environment is a greedy test
  int envs = 1;         // environments stepped in parallel (docs/agents.md: how episodes count)
  double start_states = 0;  // probability that a training episode starts from a saved state
  // Where episodes start (seed §4.2.6, start_position.h): a walk from the level's start, "" for
  // the level's own; and held-out starts, never trained from: after every greedy test, one greedy
  // episode from each (kind "heldout" in the metrics; they do not count towards `episodes`).
  std::string start;
  std::vector<std::string> test_starts;
  std::optional<std::int64_t> stop_score;  // stop after a test episode scoring at least this
  std::string out;
  bool resume = false;
};

// What the run is: everything that decides its results (not the episode count, the output
// folder or the stop rule), as text; stored in checkpoints and config.json.
Settings run_settings(const TrainConfig& c);
// The agent options and environment settings a policy was trained with.
void apply_settings(const Settings& s, TrainConfig& c);

struct EpisodeRecord {
  std::uint64_t episode = 0;  // 1-based, in the order episodes end (environment index on ties); held-out: below
  bool test = false;
  std::int64_t score = 0;
  double reward = 0;
  std::uint32_t moves = 0;
  std::uint64_t frames = 0;
  std::string outcome;        // win, lose or truncated
  double epsilon = 0;         // at the episode's end
  double loss = 0;            // the last learner loss (dqn)
  std::uint64_t total_moves = 0;  // training moves so far
  double seconds = 0;         // host time from the episode's start to its end; runs do not reproduce it
  bool saved_start = false;   // started from a saved state (--start-states); not in the metric files
  int heldout = 0;            // 1-based --test-start of a held-out greedy episode (test is true), 0: none;
                              // it shares the episode number of the test it follows
};

struct TrainStatus {
  std::uint64_t episode, episodes, moves;
  std::optional<std::int64_t> last_train, last_test, best_test;
  double epsilon, moves_per_second, eta_seconds;
  bool episode_end;  // reported once an episode is recorded (else after a move)
};

class Trainer {
 public:
  // Builds the environment and agent; with `resume`, loads the run's checkpoint and refuses one
  // made with other settings. Throws std::invalid_argument (bad names), psx::InputError (bad
  // game files), CorruptCheckpoint (bad checkpoint or mismatched run), std::runtime_error
  // (unwritable folder).
  explicit Trainer(const TrainConfig& config);
  ~Trainer();

  // Runs the remaining episodes; `progress` is called after every move and episode.
  void run(const std::function<void(const TrainStatus&)>& progress);
  const std::vector<EpisodeRecord>& records() const { return records_; }
  std::optional<std::uint64_t> first_win() const;  // the first test episode at the stop score
  const Agent& agent() const { return *agent_; }

 private:
  // One environment and its episode in progress.
  struct Slot {
    std::unique_ptr<rl::Env> env;
    std::uint64_t episodes = 0;  // episodes this environment has started
    bool test = false;
    std::ptrdiff_t from = -1;    // the saved state the next episode starts from, -1: the run's start
    int heldout = 0;             // the held-out start the episode plays from (1-based), 0: none
    std::vector<float> state, next;
    int action = 0;
    rl::StepResult result;
    std::uint64_t frames = 0;
    std::chrono::steady_clock::time_point start;
  };
  using Progress = std::function<void(const TrainStatus&)>;

  void check_start_positions();
  void plan_episode(size_t i);
  void begin_episode(size_t i);
  void offer_state(Slot& s);
  bool learn_from_move(Slot& s, const Progress& progress);
  bool end_episode(Slot& s, const Progress& progress);
  void save(bool curve) const;  // the checkpoint, and with `curve` learning_curve.png
  void restore();
  void write_metrics_from_records() const;
  void append_metrics(const EpisodeRecord& r) const;
  TrainStatus status(std::uint64_t episode, bool episode_end) const;
  std::string file(const char* name) const;

  TrainConfig config_;
  std::vector<Slot> slots_;
  std::unique_ptr<rl::ThreadPool> pool_;
  std::unique_ptr<Agent> agent_;
  Settings meta_;
  std::vector<EpisodeRecord> records_;
  std::chrono::steady_clock::time_point run_start_;  // host time of this process's run()
  std::uint64_t session_moves_ = 0, session_episodes_ = 0;
  Rng start_rng_;                            // which states are kept and which episodes use them
  std::vector<rl::Env::Snapshot> saved_;     // at most kSavedStates
  std::uint64_t offered_ = 0;                // training moves offered to saved_
  StartPosition start_;                      // config_.start parsed
  std::vector<StartPosition> test_starts_;   // config_.test_starts parsed
  std::vector<int> pending_;                 // held-out starts still to play after the last test
  std::uint64_t counted_ = 0;                // records that count towards `episodes` (not held-out)
  std::uint64_t last_test_ = 0;              // the last test's episode number (held-out episodes share it)
  std::uint64_t heldout_played_ = 0;         // held-out episodes begun: their seeds' sequence
  bool stopping_ = false;                    // the budget or stop score is reached; held-out tests finish
};

}  // namespace psxrl::agents
