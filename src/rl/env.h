// The environment: one Console + one Lua state + one integration, stepped synchronously (seed
// §3.2, DESIGN.md "The environment layer"). reset() and step() return only when the level has
// started or the move is over; the only clock is the emulated frame counter, so the same seed and
// actions always give the same observations, rewards and flags. One thread at a time: a call from
// a second thread while one is inside throws std::runtime_error("Env is in use by another
// thread") and leaves the environment as it was (util/thread_owner.h).
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/console.h"
#include "util/thread_owner.h"
#include "rl/integration.h"
#include "rl/move_delimiter.h"
#include "rl/observation.h"

namespace psx {
class Console;
}
namespace psxrl::lua {
class Host;
}

namespace psxrl::rl {

// Where integrations live: $PSXRL_GAMES, else the source tree's games/ this build was made from.
std::string default_games_dir();
// Where the build put built-in game programs (build/games).
std::string default_build_games_dir();

enum class RewardKind { Table, Score, Script };
RewardKind parse_reward_kind(const std::string& name);  // "table" | "score" | "script"

struct EnvConfig {
  std::string game = "tumble";
  std::string games_dir;        // empty: default_games_dir()
  std::string build_games_dir;  // empty: default_build_games_dir()
  UserFiles files;
  std::string obs = "simple";
  bool visual_gray = false;
  std::string reward = "table";
  double gamma = 0.9;
  // Overrides of the integration's settings; unset keeps the integration's value.
  std::optional<std::uint32_t> initial_delay, delay, max_move_frames, max_moves;
  std::optional<double> sticky;
  std::optional<bool> watch_audio;  // whether sound keeps a move going
  // The GPU renderer (docs/renderer.md): "software", or "gl" (OSMesa) drawing at `scale` (1-8).
  // Observations are native-resolution either way; the console's frame (get_screen) is scaled.
  std::string renderer = "software";
  std::uint32_t scale = 1;
  // The CPU core: "recompiler" (x86-64 code compiled per block, the faster) or "interpreter" (the
  // reference). Both compute the same bits (tests/unit/recompiler_test.cpp), so this is speed only.
  std::string cpu = "recompiler";
  // false for a tool that only boots the game and never calls reset() (psxrl record without
  // --level): the level-start states are then not asked for.
  bool starts_levels = true;
};

struct StepInfo {
  // Emulated frames of this step or reset ("game duration"): every frame the console ran, the
  // script's (start_level, after_move) included.
  std::uint64_t game_frames = 0;
  double real_seconds = 0;        // host time of this call ("real duration"); nothing depends on it
  std::int64_t score = 0;
  double time_left = 0;           // seconds, from the integration's time variable
  std::int64_t state = 0;         // the game state code
  int level = 0;
  bool hit_upper_bound = false;   // the move ran to the delimiter's frame limit
  std::uint32_t moves = 0;        // moves this episode
  double episode_reward = 0;
  std::string outcome;            // "win", "lose" or "" while the episode runs
};

struct StepResult {
  double reward = 0;
  bool terminated = false;  // win or loss
  bool truncated = false;   // move or frame cap
  StepInfo info;
};

class Env {
 public:
  // Loads the integration, boots the game and snapshots it. Throws psx::InputError for a bad
  // integration or missing user files, std::invalid_argument for a bad observation or reward name.
  explicit Env(const EnvConfig& config);
  ~Env();
  Env(const Env&) = delete;
  Env& operator=(const Env&) = delete;

  const Integration& game() const { return game_; }
  const EnvConfig& config() const { return config_; }
  ObsKind obs_kind() const { return obs_kind_; }
  const std::vector<Space>& observation_spaces() const { return spaces_; }
  const std::vector<Action>& actions() const { return game_.actions; }
  int action_count() const { return static_cast<int>(game_.actions.size()); }

  // Starts `level` (1-based) from the booted game; `seed` seeds the game's randomness (through
  // the script's on_reset) and the environment's own (sticky actions, random frame skip).
  const Observation& reset(int level, std::uint64_t seed, StepInfo* info = nullptr);
  StepResult step(int action);
  const Observation& observation() const { return obs_; }
  // Holds the environment for the calling thread until the returned object is destroyed, across
  // several calls: the Python binding holds it from step() until the observation is copied, so a
  // second thread cannot overwrite the observation mid-copy (it gets "Env is in use" instead).
  [[nodiscard]] psx::ThreadOwner::Use hold() const { return psx::ThreadOwner::Use(owner_); }

  // A moment of an episode to start later episodes from (training from saved states, the seed's
  // §5 proposal): the console's whole state, the level and its time at the level's start.
  struct Snapshot {
    int level = 0;
    double time_at_start = 0;
    psx::Console::Snapshot console;
  };
  Snapshot snapshot();
  // Starts an episode at `s` instead of the level's start: the console state is loaded, the
  // episode's moves, frames and reward restart from 0 and `seed` seeds the environment's own
  // randomness. The script's on_reset is not called (the game's randomness carries on from the
  // snapshot) and a script's own Lua variables are not part of the snapshot.
  const Observation& reset_to(const Snapshot& s, std::uint64_t seed, StepInfo* info = nullptr);
  bool episode_over() const { return done_; }
  int level() const { return level_; }

  // Move delimiting settable at run time (seed §4.1.3).
  void set_delays(std::uint32_t initial_delay, std::uint32_t delay);
  DelimiterSettings delimiter_settings() const { return delim_; }

  // Named variables as the integration declares them (scaled) and raw.
  double value(const std::string& variable) const;
  std::int64_t raw(const Variable& v) const;
  void write_raw(const Variable& v, std::int64_t value);

  // The console, for tools that show or record a game (play, record); agents never use it.
  psx::Console& console() {
    check_open();
    return *console_;
  }
  // Releases the console and the Lua state now; every later call that needs them throws
  // std::runtime_error("Env is closed"). Closing twice is allowed.
  void close();
  bool closed() const { return !console_; }
  // Called after every emulated frame of a step, with that frame's sound, for front ends that
  // show or record the game (psxrl play); it must not use the environment.
  std::function<void(std::span<const psx::StereoSample>)> on_frame;
  // "win" or "lose" when the game is in one of those states now, else "" (human play checks it
  // after every frame).
  std::string outcome() const;

 private:
  void check_open() const;
  void use_renderer();
  // Whether anything takes the console's sound (Console::set_sound_observed).
  bool samples_taken() const;
  // Sets what the SPU mixes for: the samples, a loudness watch for the move delimiter, or neither.
  void listen();
  void boot();
  void check_disc_identity(const std::string& path);
  std::uint64_t start_level(int level);  // returns the frames it ran
  // The bookkeeping every episode start shares; returns the first observation.
  const Observation& begin_episode(int level, std::uint64_t seed, double time_at_start, std::uint64_t frames,
                                   std::chrono::steady_clock::time_point t0, StepInfo* info);
  void bind_script();
  const LevelMap& map() const;
  void position(int& x, int& y, int& facing) const;
  double move_reward(std::int64_t score_delta, const std::string& outcome) const;
  void run_move(const Action& a, bool& hit_bound);
  void run_frames(int action);
  void frame_done(std::vector<std::int64_t>* watched, bool* activity);
  void encode();
  std::uint64_t next_random();
  StepInfo make_info(std::uint64_t frames, double seconds) const;

  EnvConfig config_;
  Integration game_;
  ObsKind obs_kind_;
  RewardKind reward_kind_;
  std::unique_ptr<psx::Console> console_;
  std::unique_ptr<lua::Host> lua_;
  mutable std::vector<std::optional<LevelMap>> maps_;  // read on first use
  psx::Console::Snapshot boot_state_;
  DelimiterSettings delim_;
  std::vector<const Variable*> watched_vars_;  // game_.watch resolved
  const Variable* state_var_ = nullptr;
  bool script_outcome_ = false;                // the script defines outcome()
  std::uint32_t max_moves_;
  double sticky_;

  std::vector<Space> spaces_;
  Observation obs_;
  std::vector<std::int64_t> simple_buf_;
  std::vector<float> local_buf_, episode_buf_, audio_buf_;
  std::vector<std::uint8_t> visual_buf_, rumble_buf_;
  std::vector<psx::StereoSample> frame_audio_, move_audio_;

  int level_ = 0;
  bool done_ = true;
  std::uint64_t rng_ = 0;
  std::uint32_t moves_ = 0;
  std::uint64_t episode_frames_ = 0;
  double episode_reward_ = 0;
  double time_at_start_ = 0;
  int last_action_ = 0;
  mutable psx::ThreadOwner owner_{"Env"};
};

}  // namespace psxrl::rl
