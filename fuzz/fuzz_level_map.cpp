// Fuzzes Tumble-format level maps (src/rl/level_map.h): any text either parses into a map whose
// start square and size are inside the grid, or is refused with psx::InputError.
#include <string>

#include "core/input_error.h"
#include "rl/level_map.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    psxrl::rl::LevelMap m = psxrl::rl::parse_level_map(text, "fuzz.txt");
    using psxrl::rl::LevelMap;
    if (m.width < 1 || m.height < 1 || m.width > LevelMap::kMaxSize || m.height > LevelMap::kMaxSize ||
        m.tiles.size() != static_cast<size_t>(m.width * m.height) || m.at(m.start_x, m.start_y) == psxrl::rl::Tile::Void)
      __builtin_trap();
  } catch (const psx::InputError&) {
  }
  return 0;
}
