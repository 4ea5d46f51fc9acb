// The BIOS printf (A0h:3Fh) for the HLE kernel: flags "-+ #0", width and precision (numbers or
// '*'), the h/l length modifiers (ignored: arguments are 32-bit) and the conversions
// d i u o x X c s p %.
#include <string>

#include "core/bios/hle_bios.h"

namespace psx {

std::string HleBios::format(u32 fmt_addr) const {
  std::string fmt = read_string(fmt_addr), out;
  u32 next_arg = 1;
  for (size_t i = 0; i < fmt.size(); ++i) {
    if (fmt[i] != '%') {
      out += fmt[i];
      continue;
    }
    bool left = false, plus = false, space = false, alt = false, zero = false;
    for (++i; i < fmt.size(); ++i) {
      char f = fmt[i];
      if (f == '-') left = true;
      else if (f == '+') plus = true;
      else if (f == ' ') space = true;
      else if (f == '#') alt = true;
      else if (f == '0') zero = true;
      else break;
    }
    auto number = [&](int& v) {
      if (i < fmt.size() && fmt[i] == '*') {
        v = static_cast<s32>(arg(next_arg++));
        ++i;
        return;
      }
      while (i < fmt.size() && fmt[i] >= '0' && fmt[i] <= '9') v = v * 10 + (fmt[i++] - '0');
    };
    int width = 0, precision = -1;
    number(width);
    if (width < 0) left = true, width = -width;
    if (i < fmt.size() && fmt[i] == '.') {
      ++i;
      precision = 0;
      number(precision);
    }
    while (i < fmt.size() && (fmt[i] == 'h' || fmt[i] == 'l')) ++i;
    if (i >= fmt.size()) break;
    char conv = fmt[i];
    std::string body, prefix;
    auto digits = [&](u32 v, u32 base, bool upper) {
      std::string d;
      const bool was_zero = v == 0;
      const char* set = upper ? "0123456789ABCDEF" : "0123456789abcdef";
      do d.insert(d.begin(), set[v % base]); while (v /= base);
      if (precision == 0 && was_zero) d.clear();
      while (precision > 0 && static_cast<int>(d.size()) < precision) d.insert(d.begin(), '0');
      return d;
    };
    switch (conv) {
      case 'd':
      case 'i': {
        s32 v = static_cast<s32>(arg(next_arg++));
        u32 mag = v < 0 ? 0u - static_cast<u32>(v) : static_cast<u32>(v);
        prefix = v < 0 ? "-" : plus ? "+" : space ? " " : "";
        body = digits(mag, 10, false);
        break;
      }
      case 'u': body = digits(arg(next_arg++), 10, false); break;
      case 'o': body = digits(arg(next_arg++), 8, false); if (alt && body[0] != '0') body.insert(body.begin(), '0'); break;
      case 'x':
      case 'X':
      case 'p': {
        u32 v = arg(next_arg++);
        if (conv == 'p' && precision < 0) precision = 8;
        body = digits(v, 16, conv == 'X');
        if ((alt || conv == 'p') && v) prefix = conv == 'X' ? "0X" : "0x";
        break;
      }
      case 'c': body = std::string(1, static_cast<char>(arg(next_arg++))); break;
      case 's': {
        body = read_string(arg(next_arg++));
        if (precision >= 0 && static_cast<int>(body.size()) > precision) body.resize(precision);
        break;
      }
      case '%': out += '%'; continue;
      default: out += '%'; out += conv; continue;
    }
    int pad = width - static_cast<int>(prefix.size() + body.size());
    bool zero_pad = zero && !left && precision < 0 && conv != 's' && conv != 'c';
    if (pad > 0 && left) out += prefix + body + std::string(pad, ' ');
    else if (pad > 0 && zero_pad) out += prefix + std::string(pad, '0') + body;
    else if (pad > 0) out += std::string(pad, ' ') + prefix + body;
    else out += prefix + body;
  }
  return out;
}

}  // namespace psx
