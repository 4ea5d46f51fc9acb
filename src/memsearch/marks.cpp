// Marks files (marks.h).
#include "memsearch/marks.h"

#include <sstream>

#include "core/input_error.h"

namespace psxrl::memsearch {

std::vector<Mark> parse_marks(const std::string& text, const std::string& name) {
  std::vector<Mark> marks;
  std::istringstream in(text);
  std::string line;
  for (psx::u64 n = 1; std::getline(in, line); ++n) {
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream fields(line);
    std::string frame, label, extra;
    if (!(fields >> frame)) continue;
    if (frame.find_first_not_of("0123456789") != std::string::npos || frame.size() > 12)
      throw psx::InputError::at_line(name, n, "expected FRAME LABEL with FRAME a frame number, found '" + frame + "'");
    if (!(fields >> label)) throw psx::InputError::at_line(name, n, "expected a label after the frame number");
    if (fields >> extra) throw psx::InputError::at_line(name, n, "unexpected '" + extra + "' after the label");
    for (char c : label)
      if (c == '#' || c == ',' || c == '=' || c == '@')
        throw psx::InputError::at_line(name, n, "a label may not contain # , = or @ (queries use them)");
    if (label == "start" || label == "end")
      throw psx::InputError::at_line(name, n, "'start' and 'end' name the first and last snapshots; choose another label");
    Mark m{std::stoull(frame), label};
    if (!marks.empty() && m.frame < marks.back().frame)
      throw psx::InputError::at_line(name, n, "frame " + frame + " comes before the previous mark's frame");
    marks.push_back(m);
  }
  return marks;
}

std::vector<Mark> read_marks(const std::string& path) {
  std::vector<psx::u8> bytes = psx::read_file(path);
  return parse_marks(std::string(bytes.begin(), bytes.end()), path);
}

}  // namespace psxrl::memsearch
