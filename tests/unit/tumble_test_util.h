// Helpers for the Tumble rule tests: drive the pure game logic frame by frame with pad buttons,
// and read the level maps straight from games/tumble/levels/ (independently of the game's own
// level compiler) to compute expected scores.
#pragma once
#include <fstream>
#include <string>
#include <vector>

#include "game.h"
#include "moves.h"

namespace tumble_test {

struct LevelText {
  std::vector<std::string> rows;
  int coins = 0, fruit = 0, keys = 0;
  int max_score() const { return coins * 250 + fruit * 500 + keys * 1000; }
};

inline LevelText read_level(int number) {
  char name[32];
  std::snprintf(name, sizeof name, "/level%02d.txt", number);
  std::ifstream in(std::string(TUMBLE_LEVELS_DIR) + name);
  LevelText level;
  std::string line;
  bool in_map = false;
  while (std::getline(in, line)) {
    if (in_map && !line.empty()) {
      level.rows.push_back(line);
      for (char c : line) {
        level.coins += c == 'c';
        level.fruit += c == 'f';
        level.keys += c == 'k';
      }
    }
    if (line == "map:") in_map = true;
  }
  return level;
}

// A game powered on and, optionally, started on a level through the contract's request variable.
struct Player {
  Game g{};
  explicit Player(int level = 0) {
    game_init(&g, 12345);
    if (level) {
      g.pub.request_level = level;
      frame(0);
    }
  }
  void frame(uint32_t buttons) { game_frame(&g, buttons); }
  void frames(int n, uint32_t buttons = 0) {
    for (int i = 0; i < n; ++i) frame(buttons);
  }
  // Presses `buttons` for one frame, then waits with no buttons until the move has finished or the
  // level ended. Returns the frames the move took from the press.
  int move(uint32_t buttons) {
    frame(buttons);
    int n = 1;
    while (g.pub.move != MOVE_NONE && g.pub.state == STATE_PLAYING && n < 1000) {
      frame(0);
      ++n;
    }
    return n;
  }
  void script(const std::string& moves) {
    for (char c : moves) {
      if (g.pub.state != STATE_PLAYING) return;
      switch (c) {
        case 'F': move(PAD_UP); break;
        case 'L': move(PAD_LEFT); break;
        case 'R': move(PAD_RIGHT); break;
        case 'J': move(PAD_CROSS | PAD_UP); break;
        case 'H': move(PAD_CROSS); break;
        default: break;
      }
    }
  }
};

}  // namespace tumble_test
