// The seed's Fig. 4.4 and 4.5 on Tumble: for each delimiter delay (in frames; the integration's
// initial delay covers the frames before a move shows anything), the share of moves delimited correctly and the frames a move
// takes. A move is delimited correctly when, as step() returns, the game's own `move` word is 0
// (the move is over) and the score has settled (score == score_target), the seed's test of
// "the score is still increasing". Moves: the level-1 route with its coins, fruit and key, and
// turns and forward jumps on level 3.
#include <cstdio>
#include <string>

#include "core/console.h"
#include "rl/env.h"

namespace {

using namespace psxrl::rl;

struct Tally {
  int moves = 0, correct = 0;
  double frames = 0;
};

void play(Env& env, int level, const std::string& route, Tally& t) {
  env.reset(level, 1, nullptr);
  for (char m : route) {
    if (env.episode_over()) return;
    auto r = env.step(m - '0');
    auto& c = env.console();
    bool settled = c.read32(0x80010038) == 0 && c.read32(0x8001000C) == c.read32(0x80010010);
    t.moves++;
    t.correct += settled || r.terminated;
    if (settled || r.terminated) t.frames += static_cast<double>(r.info.game_frames);
    // An early end leaves the move running: let it finish so the next move starts clean.
    while (c.read32(0x80010038) != 0 && !env.episode_over()) c.run_frame();
  }
}

void table(bool sound) {
  std::printf("\nWatching the camera, the score%s:\n\n", sound ? " and the sound" : " (no sound)");
  std::printf("| delay (frames) | delay (s) | moves | delimited correctly | mean frames per correct move |\n");
  std::printf("| --- | --- | --- | --- | --- |\n");
  EnvConfig config;
  config.watch_audio = sound;
  Env env(config);
  const std::uint32_t initial = env.delimiter_settings().initial_delay;
  for (std::uint32_t delay : {1u, 2u, 3u, 4u, 6u, 8u, 12u}) {
    env.set_delays(initial, delay);
    Tally t;
    play(env, 1, "201000001001000002020000020000", t);
    play(env, 3, "300100220000", t);
    std::printf("| %u | %.3f | %d | %.1f%% | %.1f |\n", delay, delay / 59.94, t.moves, 100.0 * t.correct / t.moves,
                t.correct ? t.frames / t.correct : 0.0);
  }
}

}  // namespace

int main() {
  std::printf("Move delimiting on Tumble (seed Fig. 4.4/4.5): level 1's full route and level 3's jumps\n");
  table(true);
  table(false);
  return 0;
}
