// `psxrl play`: plays episodes of a level, by a saved policy (greedy) or by a person at the
// keyboard or a gamepad, in an SDL window with sound or headless, printing each episode's score
// and outcome and optionally recording a video or PNG pictures (docs/play.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/game_options.h"
#include "cli/options.h"
#include "cli/play.h"
#include "cli/play_rollout.h"
#include "core/console.h"
#include "core/input_error.h"
#include "frontend/keymap.h"
#include "rl/agents/trainer.h"
#include "rl/vec_env.h"

namespace psxrl::cli {

namespace {

// The policy's agent on an environment it was trained for; a mismatch throws
// std::invalid_argument saying why.
struct LoadedPolicy {
  std::unique_ptr<rl::Env> env;
  std::unique_ptr<agents::Agent> agent;
  std::string trained_start;     // the run's --start ("" for the level's own)
  agents::StartPosition start;   // where each episode starts
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
  env.cpu = p.cpu;
  env.max_moves = p.max_moves;
  // Another game or observation is refused before booting anything (the game may not even be
  // installed); the integration version and network are checked once the environment exists.
  std::string why = agents::policy_mismatch(c.meta, env.game, env.obs, c.meta["integration_hash"], c.meta["network"]);
  if (!why.empty()) throw std::invalid_argument("cannot use the policy in " + path + ": " + why);
  LoadedPolicy l;
  l.env = std::make_unique<rl::Env>(env);
  l.agent = agents::make_agent(tc.agent, l.env->obs_kind(), l.env->observation_spaces(), l.env->action_count(),
                               tc.options);
  why = agents::policy_mismatch(c.meta, env.game, env.obs, agents::integration_hash(l.env->game()), l.agent->network());
  if (!why.empty()) throw std::invalid_argument("cannot use the policy in " + path + ": " + why);
  agents::ByteReader r(c.agent, path + " (agent)");
  l.agent->load(r);
  l.trained_start = tc.start;
  return l;
}

// Human play needs no policy: the game (default Tumble) with an observation every game has.
LoadedPolicy load_game(const PlayOptions& p, const rl::UserFiles& files) {
  rl::EnvConfig env;
  if (!p.game.empty()) env.game = p.game;
  env.obs = p.obs.empty() ? "ram" : p.obs;
  env.files = files;
  env.cpu = p.cpu;
  LoadedPolicy l;
  l.env = std::make_unique<rl::Env>(env);
  return l;
}

std::string frame_path(const std::string& dir, std::uint64_t episode, std::uint32_t move) {
  char name[48];
  std::snprintf(name, sizeof name, "ep%03llu_move%04u.png", static_cast<unsigned long long>(episode), move);
  return (std::filesystem::path(dir) / name).string();
}

// Greedy episodes of the policy, every emulated frame going through the view; an episode ends
// early when the view stops (the player closed the window, or --frames was reached).
int play_policy(LoadedPolicy& l, const PlayOptions& p, PlayView& view, RolloutWriter& rollout) {
  // Frames after the view stopped (the rest of the move under way) are emulated, not shown.
  l.env->on_frame = [&view](std::span<const psx::StereoSample> audio) {
    if (!view.stopped()) view.frame(audio);
  };
  for (std::uint64_t ep = 1; ep <= p.episodes && !view.stopped(); ++ep) {
    std::uint64_t frames = 0;
    rl::StepResult r;
    const std::uint64_t seed = rl::episode_seed(p.seed, 0, ep - 1);
    std::vector<float> s = agents::features(agents::begin_at(*l.env, p.level, l.start, seed, nullptr));
    rollout.begin(ep, p.level, seed, l.start.moves);
    if (!p.frames_dir.empty()) l.env->console().save_screenshot(frame_path(p.frames_dir, ep, 0));
    do {
      const int action = l.agent->act(s, true);
      r = l.env->step(action);
      rollout.move(action, r.reward);
      s = agents::features(l.env->observation());
      frames += r.info.game_frames;
      if (!p.frames_dir.empty()) l.env->console().save_screenshot(frame_path(p.frames_dir, ep, r.info.moves));
    } while (!r.terminated && !r.truncated && !view.stopped());
    std::string out = !r.info.outcome.empty() ? r.info.outcome : r.truncated ? "truncated" : "stopped";
    rollout.end(r, out);
    print_episode(ep, r.info.score, out, r.info.moves, frames);
  }
  return kSuccess;
}

}  // namespace

void print_episode(std::uint64_t episode, std::int64_t score, const std::string& outcome,
                   std::optional<std::uint32_t> moves, std::uint64_t frames) {
  std::string m = moves ? std::to_string(*moves) + " moves, " : "";
  std::printf("episode %llu: score %lld, %s, %s%llu frames\n", static_cast<unsigned long long>(episode),
              static_cast<long long>(score), outcome.c_str(), m.c_str(), static_cast<unsigned long long>(frames));
  std::fflush(stdout);
}

}  // namespace psxrl::cli

namespace psxrl::cli {

namespace {

void add_play_options(CLI::App& app, PlayOptions& p) {
  ViewOptions& v = p.view;
  app.add_option("--policy", p.policy, "a run folder from psxrl train, or its checkpoint.psxrl; without it, you play")
      ->type_name("PATH")
      ->transform(folder_path());
  app.add_option("--game", p.game, "game integration (default: the policy's, else tumble)")->type_name("NAME");
  app.add_option("--level", p.level, "level to play (default 1)")->type_name("N");
  app.add_option("--obs", p.obs, "observation; must be the policy's (default: the policy's)")->type_name("NAME");
  app.add_option("--episodes", p.episodes, "episodes to play (default 1)")->type_name("N");
  app.add_option("--seed", p.seed, "seed of the episodes' randomness (default 0)")->type_name("S");
  app.add_option("--max-moves", p.max_moves, "move cap per episode (default: the game's)")->type_name("N");
  app.add_option("--start", p.start,
                 "start every episode after this walk from the level's start, actions by name or number, comma\n"
                 "separated, as psxrl train --start (default: the policy's training start; \"\": the level's own)")
      ->type_name("MOVES");
  app.add_flag("--headless", p.headless, "no window and no sound (also chosen when there is no display)");
  app.add_option("--record", v.record, "record what play shows: FILE.mp4 (.mkv, .mov) with sound, or a PNG folder")
      ->type_name("OUT")
      ->transform(folder_path());
  app.add_option("--record-every", v.record_every, "record 1 picture in N frames (default 1)")->type_name("N");
  app.add_option("--frames", v.max_frames, "stop after N emulated frames shown (default: no limit)")->type_name("N");
  app.add_option("--scale", v.scale,
                 "window height in multiples of the picture's (default 2 below 400 lines); with\n"
                 "--renderer gl the picture is drawn at that multiple (1 to 8) and shown as is")
      ->type_name("K");
  p.render.add_to(app, nullptr);
  app.add_option("--window-screenshot", v.window_screenshot, "at the end, save the window's last picture as PNG")
      ->type_name("FILE");
  app.add_option("--frames-dir", p.frames_dir, "with --policy: the picture after the reset and every move as PNG")
      ->type_name("DIR")
      ->transform(folder_path());
  app.add_option("--rollout", p.rollout,
                 "with --policy: every episode's seed, start, actions, rewards and end as JSON Lines, for\n"
                 "python -m psxrl.offline export-policy (docs/offline.md)")
      ->type_name("FILE");
}

// Checks the options that need no game; returns a usage message or "".
std::string check_options(const PlayOptions& p) {
  if (p.view.record_every < 1) return "--record-every must be at least 1";
  if (p.view.scale < 0) return "--scale must be at least 1";
  if (std::string why = p.render.check(); !why.empty()) return why;
  if (p.render.renderer == "gl" && p.view.scale > static_cast<int>(psx::Console::kMaxRenderScale))
    return "--scale must be 1 to 8 with --renderer gl";
  if (p.policy.empty() && p.headless) return "human play (no --policy) needs the window: drop --headless";
  if (p.policy.empty() && !p.frames_dir.empty()) return "--frames-dir counts a policy's moves: use --record DIR";
  if (p.policy.empty() && !p.rollout.empty()) return "--rollout records a policy's moves: give --policy";
  return "";
}

// Opens the view: the window unless --headless, falling back to headless (and saying so) when no
// window can be opened. Human play without a window throws std::runtime_error.
std::unique_ptr<PlayView> open_view(PlayOptions& p, rl::Env& env) {
  p.view.title = "psxrl: " + env.game().title + ", level " + std::to_string(p.level);
  p.view.window = !p.headless;
  std::string problem = p.headless ? "" : frontend::display_problem();
  if (problem.empty() && !p.headless) {
    try {
      return std::make_unique<PlayView>(p.view, env.console());
    } catch (const std::runtime_error& e) {
      problem = e.what();
    }
  }
  if (!problem.empty()) {
    if (p.policy.empty()) throw std::runtime_error("human play needs a window: " + problem);
    std::fprintf(stderr, "psxrl play: %s: playing headless\n", problem.c_str());
  }
  p.view.window = false;
  return std::make_unique<PlayView>(p.view, env.console());
}

}  // namespace

int play_command(const std::vector<std::string>& args) {
  CLI::App app{"Plays a level in a window with sound, or headless: with --policy, a saved policy plays greedily\n"
               "(the policy's own observation; a policy made for another game, observation, network or\n"
               "integration version is refused); without it, you play. Prints each episode's score and\n"
               "outcome; --record writes a video or PNG pictures. Without a display, play runs headless.",
               "psxrl play"};
  setup_app(app, std::string(frontend::kControlsHelp) + "\n" + kAgentExitCodes);
  PlayOptions p;
  rl::UserFiles files;
  add_play_options(app, p);
  add_user_file_options(app, files);
  add_cpu_option(app, p.cpu);
  if (auto code = parse_args(app, args)) return *code;
  if (std::string why = check_options(p); !why.empty()) return usage_error(app, why);

  LoadedPolicy l;
  std::unique_ptr<PlayView> view;
  std::unique_ptr<RolloutWriter> rollout;
  try {
    if (!p.frames_dir.empty()) std::filesystem::create_directories(p.frames_dir);
    l = p.policy.empty() ? load_game(p, files) : load_policy(p, files);
    if (p.level < 1 || p.level > l.env->game().level_count)
      throw std::invalid_argument("game '" + l.env->game().name + "' has levels 1 to " +
                                  std::to_string(l.env->game().level_count) + ", not " + std::to_string(p.level));
    l.start = agents::parse_start_position(p.start.value_or(l.trained_start), l.env->actions());
    rollout = std::make_unique<RolloutWriter>(p.rollout);
    if (!l.start.moves.empty())
      std::printf("each episode starts after the walk %s (%s)\n", l.start.text.c_str(),
                  p.start ? "--start" : "the policy's training start");
    // The OpenGL renderer draws at --scale (default 2, the window's default), on SDL2's OpenGL
    // where there is a display; the window then shows its larger picture as is.
    const bool display = !p.headless && frontend::display_problem().empty();
    if (std::string error; !p.render.apply(l.env->console(), p.view.scale ? p.view.scale : 2, error, display))
      throw std::runtime_error(error);
    if (p.render.renderer == "gl") p.view.scale = 1;
    view = open_view(p, *l.env);
  } catch (const std::exception& e) {  // the policy, names, game files, output folders, no window
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  }
  try {
    int code = p.policy.empty() ? play_human(*l.env, p, l.start, *view) : play_policy(l, p, *view, *rollout);
    for (const std::string& line : view->finish()) std::printf("%s\n", line.c_str());
    return code;
  } catch (const psx::InputError& e) {
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  } catch (const psx::StateError& e) {  // a corrupt level save state is a bad input file
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  } catch (const std::invalid_argument& e) {  // a --start walk that scores or ends the episode
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "psxrl play: %s\n", e.what());
    return kProgramFailed;
  }
}

}  // namespace psxrl::cli
