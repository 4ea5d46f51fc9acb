// `psxrl play`: plays greedy episodes of a level with a saved policy, headless, printing each
// episode's score and outcome and optionally writing the picture after every move as PNG.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/game_options.h"
#include "cli/options.h"
#include "core/console.h"
#include "core/input_error.h"
#include "rl/agents/trainer.h"
#include "rl/vec_env.h"

namespace psxrl::cli {

namespace {

struct PlayOptions {
  std::string game, obs, policy, frames_dir;
  int level = 1;
  std::uint64_t episodes = 1, seed = 0;
  std::optional<std::uint32_t> max_moves;
  bool headless = false;
};

// The policy's agent on an environment it was trained for; a mismatch throws
// std::invalid_argument saying why.
struct LoadedPolicy {
  std::unique_ptr<rl::Env> env;
  std::unique_ptr<agents::Agent> agent;
};

LoadedPolicy load_policy(const PlayOptions& p, const rl::UserFiles& files) {
  std::string path = agents::checkpoint_path(p.policy);
  agents::Checkpoint c = agents::read_checkpoint(path);
  agents::TrainConfig tc;
  agents::apply_settings(c.meta, tc);
  rl::EnvConfig env = tc.env;
  if (!p.game.empty()) env.game = p.game;
  if (!p.obs.empty()) env.obs = p.obs;
  env.files = files;
  env.max_moves = p.max_moves;
  // Another game or observation is refused before booting anything (the game may not even be
  // installed); the integration version and network are checked once the environment exists.
  std::string why = agents::policy_mismatch(c.meta, env.game, env.obs, c.meta["integration_hash"], c.meta["network"]);
  if (!why.empty()) throw std::invalid_argument("cannot use the policy in " + path + ": " + why);
  LoadedPolicy l;
  l.env = std::make_unique<rl::Env>(env);
  size_t inputs = 0;
  for (const rl::Space& s : l.env->observation_spaces()) inputs += s.elements();
  l.agent = agents::make_agent(tc.agent, l.env->obs_kind(), static_cast<int>(inputs), l.env->action_count(), tc.options);
  why = agents::policy_mismatch(c.meta, env.game, env.obs, agents::integration_hash(l.env->game()), l.agent->network());
  if (!why.empty()) throw std::invalid_argument("cannot use the policy in " + path + ": " + why);
  agents::ByteReader r(c.agent, path + " (agent)");
  l.agent->load(r);
  return l;
}

std::string frame_path(const std::string& dir, std::uint64_t episode, std::uint32_t move) {
  char name[48];
  std::snprintf(name, sizeof name, "ep%03llu_move%04u.png", static_cast<unsigned long long>(episode), move);
  return (std::filesystem::path(dir) / name).string();
}

// One greedy episode; returns its last step and adds its emulated frames to `frames`.
rl::StepResult play_episode(LoadedPolicy& l, const PlayOptions& p, std::uint64_t episode, std::uint64_t& frames) {
  std::vector<float> s = agents::features(l.env->reset(p.level, rl::episode_seed(p.seed, 0, episode - 1)));
  if (!p.frames_dir.empty()) l.env->console().save_screenshot(frame_path(p.frames_dir, episode, 0));
  rl::StepResult r;
  do {
    r = l.env->step(l.agent->act(s, true));
    s = agents::features(l.env->observation());
    frames += r.info.game_frames;
    if (!p.frames_dir.empty()) l.env->console().save_screenshot(frame_path(p.frames_dir, episode, r.info.moves));
  } while (!r.terminated && !r.truncated);
  return r;
}

}  // namespace

int play_command(const std::vector<std::string>& args) {
  CLI::App app{"Plays a level with a saved policy (greedy: always the best-valued action), headless,\n"
               "printing each episode's score, outcome, moves and emulated frames. The policy's own\n"
               "observation is used; a policy made for another game, observation, network or\n"
               "integration version is refused.",
               "psxrl play"};
  setup_app(app, kAgentExitCodes);
  PlayOptions p;
  rl::UserFiles files;
  app.add_option("--policy", p.policy, "a run folder from psxrl train, or its checkpoint.psxrl")->type_name("PATH");
  app.add_option("--game", p.game, "game integration (default: the policy's)")->type_name("NAME");
  app.add_option("--level", p.level, "level to play (default 1)")->type_name("N");
  app.add_option("--obs", p.obs, "observation; must be the policy's (default: the policy's)")->type_name("NAME");
  app.add_option("--episodes", p.episodes, "episodes to play (default 1)")->type_name("N");
  app.add_option("--seed", p.seed, "seed of the episodes' randomness (default 0)")->type_name("S");
  app.add_option("--max-moves", p.max_moves, "move cap per episode (default: the game's)")->type_name("N");
  app.add_option("--frames-dir", p.frames_dir, "write the picture after the reset and every move as PNG here")
      ->type_name("DIR");
  app.add_flag("--headless", p.headless, "no window (the only mode so far: play is always headless)");
  add_user_file_options(app, files);
  if (auto code = parse_args(app, args)) return *code;
  if (p.policy.empty()) return usage_error(app, "--policy is required (human play needs the window, not built yet)");

  LoadedPolicy l;
  try {
    if (!p.frames_dir.empty()) std::filesystem::create_directories(p.frames_dir);
    l = load_policy(p, files);
    if (p.level < 1 || p.level > l.env->game().level_count)
      throw std::invalid_argument("game '" + l.env->game().name + "' has levels 1 to " +
                                  std::to_string(l.env->game().level_count) + ", not " + std::to_string(p.level));
  } catch (const std::exception& e) {  // the policy, names, game files, the frames folder
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  }
  try {
    for (std::uint64_t ep = 1; ep <= p.episodes; ++ep) {
      std::uint64_t frames = 0;
      rl::StepResult r = play_episode(l, p, ep, frames);
      std::printf("episode %llu: score %lld, %s, %u moves, %llu frames\n", static_cast<unsigned long long>(ep),
                  static_cast<long long>(r.info.score), r.info.outcome.empty() ? "truncated" : r.info.outcome.c_str(),
                  r.info.moves, static_cast<unsigned long long>(frames));
      std::fflush(stdout);
    }
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kProgramFailed;
  }
  return kSuccess;
}

}  // namespace psxrl::cli
