// Level maps for position-based observations (the seed's §3.2.5 ASCII maps): a grid of tiles
// with a start square and facing, read from the text format Tumble's levels are built from
// (games/tumble/README.md "Levels"). Users write Kula World's maps in the same format.
#pragma once
#include <string>
#include <vector>

namespace psxrl::rl {

enum class Tile : char {
  Void = '.',
  Floor = '#',
  Start = 'S',
  Exit = 'E',
  Spikes = '^',
  Crumbling = '%',
  Coin = 'c',
  Fruit = 'f',
  Key = 'k',
};

struct LevelMap {
  static constexpr int kMaxSize = 16;

  std::string name;
  int time_seconds = 0;
  int facing = 0;  // 0 north, 1 east, 2 south, 3 west
  int width = 0, height = 0;
  int start_x = 0, start_y = 0;
  std::vector<Tile> tiles;  // row-major, row 0 is north

  // Tile at (x, y); outside the map is Void.
  Tile at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width || y >= height) return Tile::Void;
    return tiles[static_cast<size_t>(y * width + x)];
  }
};

// Parses a map's text; errors are psx::InputError naming `file:line` and what was expected.
LevelMap parse_level_map(const std::string& text, const std::string& file);
LevelMap read_level_map(const std::string& path);

}  // namespace psxrl::rl
