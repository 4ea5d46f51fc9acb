// Level map text format (see level_map.h and games/tumble/README.md "Levels").
#include "rl/level_map.h"

#include <sstream>

#include "core/input_error.h"

namespace psxrl::rl {

namespace {

constexpr std::string_view kTileChars = ".#SE^%cfk ";

bool parse_header(const std::string& line, LevelMap& map, const std::string& file, size_t ln) {
  auto fail = [&](const std::string& what) { throw psx::InputError::at_line(file, ln, what); };
  if (line.rfind("name: ", 0) == 0) {
    map.name = line.substr(6);
  } else if (line.rfind("time: ", 0) == 0) {
    std::string v = line.substr(6);
    if (v.empty() || v.size() > 3 || v.find_first_not_of("0123456789") != std::string::npos) fail("time: expected seconds 1..999");
    map.time_seconds = std::stoi(v);
    if (map.time_seconds < 1) fail("time: expected seconds 1..999");
  } else if (line.rfind("facing: ", 0) == 0) {
    static constexpr std::string_view kDirs = "NESW";
    size_t dir = line.size() == 9 ? kDirs.find(line[8]) : std::string_view::npos;
    if (dir == std::string_view::npos) fail("facing: expected N, E, S or W");
    map.facing = static_cast<int>(dir);
  } else if (line == "map:") {
    return true;
  } else {
    fail("expected '# comment', 'name:', 'time:', 'facing:' or 'map:'");
  }
  return false;
}

}  // namespace

LevelMap parse_level_map(const std::string& text, const std::string& file) {
  LevelMap map;
  map.facing = -1;
  std::istringstream in(text);
  std::string line;
  size_t ln = 0;
  bool in_map = false;
  std::vector<std::string> rows;
  while (std::getline(in, line)) {
    ++ln;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!in_map) {
      if (line.empty() || line[0] == '#') continue;
      in_map = parse_header(line, map, file, ln);
      if (in_map && (map.name.empty() || map.time_seconds == 0 || map.facing < 0))
        throw psx::InputError::at_line(file, ln, "missing name:, time: or facing: before map:");
      continue;
    }
    if (line.size() > LevelMap::kMaxSize)
      throw psx::InputError::at_line(file, ln, "map rows are at most 16 tiles wide");
    for (char c : line)
      if (kTileChars.find(c) == std::string_view::npos)
        throw psx::InputError::at_line(file, ln, std::string("expected a map character (. # S E ^ % c f k), found '") + c + "'");
    rows.push_back(line);
  }
  while (!rows.empty() && rows.back().find_first_not_of(' ') == std::string::npos) rows.pop_back();
  if (!in_map) throw psx::InputError::at_line(file, ln, "expected 'map:' followed by the map rows");
  if (rows.empty() || rows.size() > LevelMap::kMaxSize)
    throw psx::InputError::at_line(file, ln, "expected 1 to 16 map rows after 'map:'");
  map.height = static_cast<int>(rows.size());
  for (const auto& r : rows) map.width = std::max(map.width, static_cast<int>(r.size()));
  map.tiles.assign(static_cast<size_t>(map.width * map.height), Tile::Void);
  int starts = 0, exits = 0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < static_cast<int>(rows[y].size()); ++x) {
      char c = rows[y][x] == ' ' ? '.' : rows[y][x];
      map.tiles[static_cast<size_t>(y * map.width + x)] = static_cast<Tile>(c);
      if (c == 'S') starts++, map.start_x = x, map.start_y = y;
      if (c == 'E') exits++;
    }
  }
  if (starts != 1 || exits != 1)
    throw psx::InputError::at_line(file, ln, "expected exactly one 'S' and one 'E' in the map, found " +
                                                 std::to_string(starts) + " and " + std::to_string(exits));
  return map;
}

LevelMap read_level_map(const std::string& path) {
  auto bytes = psx::read_file(path);
  return parse_level_map(std::string(bytes.begin(), bytes.end()), path);
}

}  // namespace psxrl::rl
