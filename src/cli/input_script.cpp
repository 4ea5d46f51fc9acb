// Parser for `psxrl run --input` scripts (see input_script.h).
#include "cli/input_script.h"

#include <sstream>
#include <utility>

#include "core/console.h"
#include "core/sio/pad_names.h"

namespace psxrl::cli {

namespace {

bool parse_number(const std::string& s, psx::u64 limit, psx::u64& out) {
  if (s.empty() || s.size() > 19 || s.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stoull(s);
  return out <= limit;
}

psx::u16 parse_buttons(const std::string& field, const std::string& name, size_t line) {
  psx::u16 bits = 0;
  size_t start = 0;
  for (;;) {
    size_t plus = field.find('+', start);
    std::string one = field.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
    std::optional<psx::u16> bit = psx::pad_button_from_name(one);
    if (!bit)
      throw psx::InputError::at_line(name, line, "expected a button name (" + std::string(psx::kPadButtonNameList) +
                                                     ") in '" + field + "', found '" + one + "'");
    bits |= *bit;
    if (plus == std::string::npos) return bits;
    start = plus + 1;
  }
}

}  // namespace

std::vector<InputPress> parse_input_script(const std::string& text, const std::string& name) {
  std::vector<InputPress> presses;
  std::istringstream in(text);
  std::string raw;
  for (size_t line = 1; std::getline(in, raw); ++line) {
    if (size_t hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
    std::istringstream fields(raw);
    std::string frame, buttons, hold, extra;
    if (!(fields >> frame)) continue;
    InputPress p;
    if (!parse_number(frame, UINT64_MAX / 2, p.frame))
      throw psx::InputError::at_line(name, line, "expected a frame number, found '" + frame + "'");
    if (!presses.empty() && p.frame < presses.back().frame)
      throw psx::InputError::at_line(name, line, "expected a frame number not below the previous line's " +
                                                     std::to_string(presses.back().frame) + ", found " + frame);
    if (!(fields >> buttons))
      throw psx::InputError::at_line(name, line, "expected buttons after the frame number (e.g. up+cross)");
    p.buttons = parse_buttons(buttons, name, line);
    if (fields >> hold) {
      psx::u64 n = 0;
      if (!parse_number(hold, 1000000, n) || n == 0)
        throw psx::InputError::at_line(name, line, "expected a hold time of 1 to 1000000 frames, found '" + hold + "'");
      p.hold = static_cast<psx::u32>(n);
    }
    if (fields >> extra)
      throw psx::InputError::at_line(name, line, "expected the end of the line after FRAME BUTTONS [HOLD_FRAMES], found '" +
                                                     extra + "'");
    presses.push_back(p);
  }
  return presses;
}

std::vector<InputPress> read_input_script(const std::string& path) {
  std::vector<uint8_t> bytes = psx::read_file(path);
  return parse_input_script(std::string(bytes.begin(), bytes.end()), path);
}

}  // namespace psxrl::cli
