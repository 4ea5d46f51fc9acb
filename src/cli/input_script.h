// Scripted pad input for `psxrl run --input FILE`: a text file of timed button presses on port 1,
// one per line, `FRAME BUTTONS [HOLD_FRAMES]`. FRAME counts emulated frames from 0 (the first
// frame after boot), BUTTONS joins pad button names with '+', HOLD_FRAMES (default 1) is how many
// frame ends the buttons stay down. '#' starts a comment; blank lines are ignored.
#pragma once
#include <string>
#include <vector>

#include "core/types.h"

namespace psxrl::cli {

struct InputPress {
  psx::u64 frame = 0;     // pressed just before this frame runs
  psx::u16 buttons = 0;   // pad_button bits
  psx::u32 hold = 1;      // frames held
};

// Parses a script's text; `name` is used in error messages. Throws psx::InputError naming
// name:line and what was expected. Lines must be in non-decreasing frame order.
std::vector<InputPress> parse_input_script(const std::string& text, const std::string& name);
// Reads and parses a script file (psx::InputError when it cannot be read).
std::vector<InputPress> read_input_script(const std::string& path);

}  // namespace psxrl::cli
