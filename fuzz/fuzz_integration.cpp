// Fuzzes game integration manifests (game.toml, src/rl/integration.h). parse_integration resolves
// paths against the folder but needs no file to exist; any text either parses or is refused with
// psx::InputError naming file:line.
#include <string>

#include "core/input_error.h"
#include "rl/integration.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    psxrl::rl::Integration g = psxrl::rl::parse_integration(text, "game.toml", "/nonexistent/game", "/nonexistent/build");
    // The manifest's path patterns are expanded for every level an environment starts.
    const psxrl::rl::UserFiles files{"disc.cue", "bios.bin", "states", "maps"};
    for (int level : {1, g.level_count}) {
      psxrl::rl::expand(g.state_pattern, level, g, files);
      psxrl::rl::expand(g.map_pattern, level, g, files);
    }
  } catch (const psx::InputError&) {
  }
  return 0;
}
