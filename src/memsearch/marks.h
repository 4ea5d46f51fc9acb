// Marks for a headless recording (`psxrl record --marks FILE`): what a player at the window would
// set with a key, written down as text. One mark per line, `FRAME LABEL`: the mark is set when
// frame FRAME (counted from 0, as input scripts count) ends. '#' starts a comment.
#pragma once
#include <string>
#include <vector>

#include "memsearch/session.h"

namespace psxrl::memsearch {

// Throws psx::InputError naming name:line and what was expected. Frames must not decrease.
std::vector<Mark> parse_marks(const std::string& text, const std::string& name);
std::vector<Mark> read_marks(const std::string& path);

}  // namespace psxrl::memsearch
