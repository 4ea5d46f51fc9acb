// The learning curve's bitmap font (see plot_font.h): Tumble's 5x7 font (games/tumble/tools/font5x7.h).
#include "rl/agents/plot_font.h"

#include "font5x7.h"

namespace psxrl::agents {

const char* glyph(char c) {
  for (const Font5x7Glyph& g : kFont5x7)
    if (g.ch == c) return g.rows;
  return nullptr;
}

}  // namespace psxrl::agents
