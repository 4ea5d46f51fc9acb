// `psxrl train`: trains an agent on a game level (seed §4.2.1) with a live progress line, writing
// a run folder (config.json, metrics.csv, metrics.jsonl, learning_curve.png, checkpoint.psxrl).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/game_options.h"
#include "cli/options.h"
#include "core/console.h"
#include "core/input_error.h"
#include "rl/agents/trainer.h"

namespace psxrl::cli {

namespace {

std::string duration(double seconds) {
  auto s = static_cast<long long>(seconds);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%lldh%02lldm", s / 3600, s / 60 % 60);
  else std::snprintf(buf, sizeof buf, "%lldm%02llds", s / 60, s % 60);
  return buf;
}

std::string score(const std::optional<std::int64_t>& v) { return v ? std::to_string(*v) : "-"; }

// The progress line: redrawn in place on a terminal at most 4 times a second, else one line per
// finished episode.
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet) : quiet_(quiet), tty_(isatty(2) != 0) {}
  void operator()(const agents::TrainStatus& s) {
    if (quiet_ || (!tty_ && !s.episode_end)) return;
    auto now = std::chrono::steady_clock::now();
    if (tty_ && !s.episode_end && now - last_ < std::chrono::milliseconds(250)) return;
    last_ = now;
    char line[256];
    std::snprintf(line, sizeof line,
                  "episode %llu/%llu  moves %llu  train %s  test %s  best %s  eps %.3f  %.1f moves/s  ETA %s",
                  static_cast<unsigned long long>(s.episode), static_cast<unsigned long long>(s.episodes),
                  static_cast<unsigned long long>(s.moves), score(s.last_train).c_str(), score(s.last_test).c_str(),
                  score(s.best_test).c_str(), s.epsilon, s.moves_per_second, duration(s.eta_seconds).c_str());
    std::fprintf(stderr, tty_ ? "\r%-110s" : "%s\n", line);
  }
  void finish() {
    if (!quiet_ && tty_) std::fputc('\n', stderr);
  }

 private:
  bool quiet_, tty_;
  std::chrono::steady_clock::time_point last_{};
};

void add_train_options(CLI::App& app, agents::TrainConfig& c, std::string& obs, std::string& exploration) {
  agents::AgentOptions& o = c.options;
  app.add_option("--game", c.env.game, "game integration (default tumble)")->type_name("NAME");
  app.add_option("--level", c.level, "level to train on (default 1)")->type_name("N");
  app.add_option("--agent", c.agent, "random, q (tabular Q-learning) or dqn (default)")->type_name("NAME");
  app.add_option("--obs", obs, "observation: simple (q, random), local (dqn), visual, multimodal, episode, audio")
      ->type_name("NAME");
  app.add_option("--episodes", c.episodes, "episodes in all, test episodes included (default 1000)")->type_name("N");
  app.add_option("--gamma", c.env.gamma, "discount; rewards are in units of 1 - gamma (default 0.9)")->type_name("G");
  app.add_option("--seed", c.seed, "seed of the agent, exploration and episodes (default 0)")->type_name("S");
  app.add_option("--out", c.out, "run folder (default runs/GAME-lLEVEL-AGENT-OBS-sSEED)")
      ->type_name("DIR")
      ->transform(folder_path());
  app.add_flag("--resume", c.resume, "continue the run in --out from its checkpoint (same options)");
  app.add_option("--max-moves", c.env.max_moves, "move cap per episode (default: the game's)")->type_name("N");
  app.add_option("--test-every", c.test_every, "every Nth episode is a greedy test (default 10: 9 train, 1 test)")
      ->type_name("N");
  app.add_option("--envs", c.envs,
                 "environments collecting experience in parallel (default 1; more cannot --resume)")
      ->type_name("K");
  app.add_option("--start-states", c.start_states,
                 "probability that a training episode starts from a state saved in earlier ones (default 0)")
      ->type_name("P");
  app.add_option("--start", c.start,
                 "start every episode here: a walk from the level's start, actions by name or number, comma "
                 "separated (e.g. LOOKLEFT,JUMPFORWARD); it must collect nothing and end nothing (seed 4.2.6)")
      ->type_name("MOVES");
  app.add_option("--test-start", c.test_starts,
                 "a held-out start (a walk, as --start), never trained from: after every test, one greedy "
                 "episode from each; repeat for several (needs --envs 1)")
      ->type_name("MOVES");
  app.add_option("--stop-score", c.stop_score, "stop after a test episode scoring at least S")->type_name("S");
  app.add_option("--alpha", o.alpha, "q: learning rate of the table (default 0.5)")->type_name("A");
  app.add_option("--lr", o.lr, "dqn: Adam learning rate (default 0.004 visual/multimodal, else 0.0025)")
      ->type_name("LR");
  app.add_option("--hidden", o.hidden, "dqn: width of the 4 hidden layers (default 32)")->type_name("N");
  app.add_option("--epochs", o.epochs,
                 "dqn: gradient steps on each replay batch, one batch per training move (default 15, the seed's; "
                 "the learner's cost per move is proportional)")
      ->type_name("N")
      ->check(CLI::Range(1, 1000));
  app.add_option("--batch", o.batch, "dqn: replay batch size (default 80)")->type_name("N")->check(CLI::Range(1, 100000));
  app.add_option("--epsilon-moves", o.epsilon_moves, "training moves over which epsilon falls 1.0 -> 0.1 (default 10000)")
      ->type_name("N");
  app.add_option("--exploration", exploration,
                 "exploratory moves: epsilon (uniform, default) or q-weighted (seed Eq. 4.1)")
      ->type_name("KIND");
  app.add_flag("--linear-output", o.linear_output, "dqn: linear output layer instead of tanh");
  app.add_flag("--target-network", o.target_network, "dqn: bootstrap from a target network");
  app.add_option("--target-sync", o.target_sync, "dqn: moves between target network syncs (default 500)")->type_name("N");
  app.add_flag("--double-dqn", o.double_dqn, "dqn: Double DQN targets (implies --target-network)");
  app.add_option("--reward", c.env.reward, "table (seed Table 3.3, default), score or script")->type_name("KIND");
  add_user_file_options(app, c.env.files);
  add_cpu_option(app, c.env.cpu);
}

// `resumed_at`: the records a resumed run started with; throughput counts this process's only.
void print_summary(const agents::Trainer& t, const agents::TrainConfig& c, double seconds, size_t resumed_at) {
  std::optional<std::int64_t> best;
  std::uint64_t best_at = 0;
  for (const agents::EpisodeRecord& r : t.records())
    if (r.test && !r.heldout && (!best || r.score > *best)) best = r.score, best_at = r.episode;
  size_t heldout = 0;
  for (const agents::EpisodeRecord& r : t.records()) heldout += r.heldout != 0;
  std::printf("trained %zu episodes (%llu training moves) in %.1f s; best test score %s", t.records().size() - heldout,
              static_cast<unsigned long long>(t.agent().moves()), seconds, score(best).c_str());
  if (best) std::printf(" (first at episode %llu)", static_cast<unsigned long long>(best_at));
  if (auto w = t.first_win()) std::printf("; first test win at episode %llu", static_cast<unsigned long long>(*w));
  if (heldout) std::printf("; %zu held-out tests", heldout);
  std::uint64_t moves = 0;
  for (size_t i = resumed_at; i < t.records().size(); ++i) moves += t.records()[i].moves;
  if (seconds > 0)
    std::printf("\nthroughput: %.1f moves/s (test moves included), %.1f learner updates/s", moves / seconds,
                static_cast<double>(t.agent().updates()) / seconds);
  std::printf("\nrun folder: %s\n", c.out.c_str());
}

}  // namespace

int train_command(const std::vector<std::string>& args) {
  CLI::App app{"Trains an agent on a game level: nine epsilon-greedy training episodes, then one greedy\n"
               "test episode (seed 4.2.1). Writes config.json, metrics.csv, metrics.jsonl,\n"
               "learning_curve.png and checkpoint.psxrl (after every episode) to the run folder.",
               "psxrl train"};
  setup_app(app, kAgentExitCodes);
  agents::TrainConfig c;
  std::string obs, exploration = "epsilon";
  bool quiet = false;
  add_train_options(app, c, obs, exploration);
  app.add_flag("--quiet", quiet, "no progress line");
  if (auto code = parse_args(app, args)) return *code;
  c.env.obs = obs.empty() ? agents::default_obs(c.agent) : obs;
  if (app.count("--lr") == 0) c.options.lr = agents::default_lr(c.env.obs);
  if (c.out.empty())
    c.out = "runs/" + c.env.game + "-l" + std::to_string(c.level) + "-" + c.agent + "-" + c.env.obs + "-s" +
            std::to_string(c.seed);

  std::unique_ptr<agents::Trainer> trainer;
  try {
    c.options.exploration = agents::parse_exploration(exploration);
    trainer = std::make_unique<agents::Trainer>(c);
  } catch (const std::exception& e) {  // names, levels, game files, checkpoints, the run folder
    std::fprintf(stderr, "psxrl train: %s\n", e.what());
    return kBadInput;
  }
  ProgressLine progress(quiet);
  const size_t resumed_at = trainer->records().size();
  auto start = std::chrono::steady_clock::now();
  try {
    trainer->run([&](const agents::TrainStatus& s) { progress(s); });
  } catch (const std::exception& e) {
    progress.finish();
    // A bad game file (a corrupt level save state included) is bad input; anything else is the
    // emulated program's failure. The checkpoint is mentioned only when one was written.
    const bool bad_input = dynamic_cast<const psx::InputError*>(&e) || dynamic_cast<const psx::StateError*>(&e);
    const std::string checkpoint = c.out + "/" + agents::kCheckpointFile;
    std::string kept = std::filesystem::exists(checkpoint) ? " (the last checkpoint, " + checkpoint + ", is intact)"
                                                           : " (no checkpoint was written yet)";
    std::fprintf(stderr, "psxrl train: %s%s\n", e.what(), kept.c_str());
    return bad_input ? kBadInput : kProgramFailed;
  }
  progress.finish();
  print_summary(*trainer, c, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                resumed_at);
  return kSuccess;
}

}  // namespace psxrl::cli
