// HLE kernel: the file functions (psx-spx "BIOS File Functions"): open/lseek/read/write/close,
// getc/putc/getchar/gets, cd, firstfile2/nextfile, erase/rename/undelete/format, _get_errno/
// _get_error and the device table calls, over three devices: "tty" (the console: output to the
// host TTY, no input), "cdrom" (hle_cdfs.cpp) and "bu00"/"bu10", the memory cards
// (hle_memcard.cpp). Handles 0 and 1 start open on the TTY, as the BIOS opens stdin/stdout
// before it starts a program.
#include "core/bios/hle_bios.h"

#include <cctype>

#include "core/bus.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kB0 = 0xB0;
constexpr u32 kRegA0 = 4, kRegA1 = 5, kRegA2 = 6, kRegRa = 31;
constexpr u32 kFail = 0xFFFFFFFF;
constexpr u32 kPatternLength = 20;  // a direntry's name field holds 20 characters with the NUL

struct DevicePath {
  u32 device = kDevNone, port = 0;
  std::string rest;  // what follows the ':'
};

// "tty:", "cdrom:" (a port digit is ignored, psx-spx "BIOS CDROM Functions"), "bu00:" (slot 1)
// and "bu10:" (slot 2). The multitap names bu01..bu13 address cards the console does not have.
bool parse_device(const std::string& path, DevicePath& out) {
  size_t colon = path.find(':');
  if (colon == std::string::npos) return false;
  std::string name = path.substr(0, colon);
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  out.rest = path.substr(colon + 1);
  auto digits_after = [&](size_t n) {
    for (size_t i = n; i < name.size(); ++i)
      if (!std::isdigit(static_cast<unsigned char>(name[i]))) return false;
    return true;
  };
  if (name.rfind("tty", 0) == 0 && digits_after(3)) {
    out.device = kDevTty;
  } else if (name.rfind("cdrom", 0) == 0 && digits_after(5)) {
    out.device = kDevCdrom;
  } else if (name.size() == 4 && name.rfind("bu", 0) == 0 && (name[2] == '0' || name[2] == '1') && name[3] == '0') {
    out.device = kDevCard;
    out.port = static_cast<u32>(name[2] - '0');
  } else {
    return false;
  }
  return true;
}

// firstfile2's pattern: '*' ends it and stands for any rest, so it becomes '?' up to the name
// field's length; an empty pattern matches every name.
std::string expand_pattern(const std::string& pattern) {
  std::string out;
  for (char c : pattern) {
    if (c == '*') return out + std::string(kPatternLength - std::min<size_t>(out.size(), kPatternLength), '?');
    out += c;
  }
  return out.empty() ? std::string(kPatternLength, '?') : out;
}

template <size_t N>
void store(std::array<char, N>& dst, const std::string& s) {
  dst.fill(0);
  for (size_t i = 0; i < s.size() && i + 1 < N; ++i) dst[i] = s[i];
}

template <size_t N>
std::string load(const std::array<char, N>& src) {
  std::string s;
  for (size_t i = 0; i < N && src[i]; ++i) s += src[i];
  return s;
}
}  // namespace

bool hle_name_matches(const std::string& name, const std::string& pattern) {
  for (size_t i = 0; i < name.size(); ++i) {
    if (i >= pattern.size()) return false;
    if (pattern[i] != '?' && std::toupper(static_cast<unsigned char>(pattern[i])) !=
                                 std::toupper(static_cast<unsigned char>(name[i])))
      return false;
  }
  return pattern.size() == name.size() || pattern[name.size()] == '?';
}

// The file, CD-ROM and memory card calls; tried before the TTY calls, which only print.
bool HleBios::io_call(u32 table, u32 fn) {
  if (table == kA0) return file_call(fn) || cd_call(fn) || card_call(kA0, fn);
  return file_call_b0(fn) || card_call(kB0, fn);
}

HleFile* HleBios::file_at(u32 fd) {
  if (fd >= HleIoState::kHandles || io_.files[fd].device == kDevNone) return nullptr;
  return &io_.files[fd];
}

u32 HleBios::file_fail(HleFile* f, u32 err) {
  io_.last_error = err;
  if (f) f->error = err;
  return kFail;
}

// A0h:00h-09h and 3Bh; B0h:32h-3Ch are the same functions (psx-spx lists both numbers).
bool HleBios::file_call(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1), a2 = cpu_.reg(kRegA2);
  switch (fn) {
    case 0x00: return_to_caller(file_open(a0, a1)); return true;
    case 0x01: return_to_caller(file_lseek(a0, a1, a2)); return true;
    case 0x02: return_after_events(file_read(a0, a1, a2)); return true;
    case 0x03: return_after_events(file_write(a0, a1, a2)); return true;
    case 0x04: return_to_caller(file_close(a0)); return true;
    case 0x05: {  // ioctl(fd, cmd, arg): only the TTY takes commands, and this one has no settings
      HleFile* f = file_at(a0);
      return_to_caller(!f ? file_fail(nullptr, kEBadF) : f->device == kDevTty ? 0 : file_fail(f, kEInval));
      return true;
    }
    case 0x07:  // isatty(fd): DCB flag bit 1, set only for the DUART TTY, which no console has here
      return_to_caller(0);
      return true;
    case 0x08: {  // getc(fd): read(fd, tmp, 1); no TTY input, and one byte is never a whole sector
      HleFile* f = file_at(a0);
      return_to_caller(!f ? file_fail(nullptr, kEBadF) : f->device == kDevTty ? kFail : file_fail(f, kEInval));
      return true;
    }
    case 0x09: {  // putc(char, fd): write(fd, tmp, 1)
      HleFile* f = file_at(a1);
      u32 r = !f ? file_fail(nullptr, kEBadF) : f->device == kDevCard ? file_fail(f, kEInval) : 0;
      if (f && f->device == kDevTty) print(std::string(1, static_cast<char>(a0))), r = 1;
      return_to_caller(r);
      return true;
    }
    case 0x3B:  // getchar: no TTY input reaches the console, so no character is waited for
      return_to_caller(0);
      return true;
    case 0x3D:  // gets(dst): with no TTY input the line ends at once: empty, its LF echoed
      poke8(a0, 0);
      print("\n");
      return_to_caller(a0);
      return true;
    default: return false;
  }
}

bool HleBios::file_call_b0(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1);
  if ((fn >= 0x32 && fn <= 0x37) || fn == 0x39) return file_call(fn - 0x32);
  switch (fn) {
    case 0x3A: return file_call(0x08);
    case 0x3B: return file_call(0x09);
    case 0x3C: return file_call(0x3B);
    case 0x3E: return file_call(0x3D);
    case 0x40: {  // cd(path): only cdrom: has directories; the path is not checked
      DevicePath d;
      bool ok = parse_device(read_string(a0), d) && d.device == kDevCdrom;
      if (ok) store(io_.cd_dir, d.rest);
      return_to_caller(ok ? 1 : 0);
      return true;
    }
    case 0x41: {  // format(device): memory cards only
      DevicePath d;
      u32 err = !parse_device(read_string(a0), d) ? kENoDev : d.device != kDevCard ? kEInval : card_format(d.port);
      if (err) file_fail(nullptr, err);
      return_to_caller(err ? 0 : 1);
      return true;
    }
    case 0x42: return_to_caller(first_file(a0, a1)); return true;
    case 0x43: return_to_caller(next_file(a0)); return true;
    case 0x44:  // rename(old, new)
    case 0x46: {  // undelete(path)
      u32 err = fn == 0x44 ? file_rename(a0, a1) : file_undelete(a0);
      if (err) file_fail(nullptr, err);
      return_to_caller(err ? 0 : 1);
      return true;
    }
    case 0x45: {  // erase(path): memory cards only
      DevicePath d;
      bool ok = parse_device(read_string(a0), d) && d.device == kDevCard && card_erase(d.port, d.rest);
      if (!ok) io_.last_error = kENoEnt;
      return_to_caller(ok ? 1 : 0);
      return true;
    }
    // AddDevice/RemoveDevice: the kernel's devices are its own here; a program's device control
    // block is accepted but its functions are not called (the TTY stays the host's console).
    case 0x47:
    case 0x48: return_to_caller(1); return true;
    case 0x49:  // PrintInstalledDevices: the short and long names of the devices
      print("\ttty:\tCONSOLE\n\tcdrom:\tCD-ROM\n\tbu:\tMEMORY CARD\n");
      return_to_caller(0);
      return true;
    case 0x54: return_to_caller(io_.last_error); return true;  // _get_errno
    case 0x55: {                                                // _get_error(fd)
      HleFile* f = file_at(a0);
      return_to_caller(f ? f->error : kFail);
      return true;
    }
    default: return false;
  }
}

u32 HleBios::file_open(u32 path_addr, u32 mode) {
  u32 fd = 0;
  while (fd < HleIoState::kHandles && io_.files[fd].device != kDevNone) ++fd;
  if (fd == HleIoState::kHandles) return file_fail(nullptr, kEMFile);
  DevicePath d;
  if (!parse_device(read_string(path_addr), d)) return file_fail(nullptr, kENoDev);
  HleFile f;
  f.device = d.device, f.port = d.port, f.mode = mode;
  u32 err = 0;
  if (d.device == kDevCdrom) err = cd_open(d.rest, f);
  else if (d.device == kDevCard) err = card_open(d.port, d.rest, mode, f);
  if (err) return file_fail(nullptr, err);
  io_.files[fd] = f;
  return fd;
}

u32 HleBios::file_read(u32 fd, u32 dst, u32 len) {
  HleFile* f = file_at(fd);
  if (!f) return file_fail(nullptr, kEBadF);
  switch (f->device) {
    case kDevTty: return 0;  // no TTY input
    case kDevCdrom: return cd_read(*f, dst, len);
    default: return card_transfer(*f, dst, len, false);
  }
}

u32 HleBios::file_write(u32 fd, u32 src, u32 len) {
  HleFile* f = file_at(fd);
  if (!f) return file_fail(nullptr, kEBadF);
  switch (f->device) {
    case kDevTty: {
      std::string s;
      for (u32 i = 0; i < len; ++i) s += static_cast<char>(peek8(src + i));
      print(s);
      return len;
    }
    case kDevCdrom: return 0;  // "Writing to the cdrom returns 0"
    default: return card_transfer(*f, src, len, true);
  }
}

// Seek type 2 (from the end) leaves the pointer where it is, as the BIOS's does; no check
// against the file's size (psx-spx "lseek").
u32 HleBios::file_lseek(u32 fd, u32 offset, u32 whence) {
  HleFile* f = file_at(fd);
  if (!f) return file_fail(nullptr, kEBadF);
  if (whence > 2) return file_fail(f, kEInval);
  if (whence == 0) f->pos = offset;
  if (whence == 1) f->pos += offset;
  return f->pos;
}

u32 HleBios::file_close(u32 fd) {
  HleFile* f = file_at(fd);
  if (!f) return file_fail(nullptr, kEBadF);
  *f = HleFile{};
  return fd;
}

// rename(old, new): both names on the same memory card (error 12h across devices); 0 or an
// error number.
u32 HleBios::file_rename(u32 from_addr, u32 to_addr) {
  DevicePath from, to;
  if (!parse_device(read_string(from_addr), from) || !parse_device(read_string(to_addr), to)) return kENoDev;
  if (from.device != to.device || from.port != to.port) return kEXDev;
  if (from.device != kDevCard) return kEInval;
  return card_rename(from.port, from.rest, to.rest);
}

// undelete(path): a deleted memory card file; 0 or an error number.
u32 HleBios::file_undelete(u32 path_addr) {
  DevicePath d;
  if (!parse_device(read_string(path_addr), d)) return kENoDev;
  return d.device == kDevCard ? card_undelete(d.port, d.rest) : kEInval;
}

// firstfile2(path, direntry): the device and directory come from the path, the pattern from its
// last component.
u32 HleBios::first_file(u32 path_addr, u32 entry) {
  DevicePath d;
  if (!parse_device(read_string(path_addr), d) || d.device == kDevTty) return 0;
  std::string dir, pattern = d.rest;
  if (d.device == kDevCdrom) {
    std::string full = cd_full_path(d.rest);
    size_t slash = full.find_last_of('\\');
    dir = full.substr(0, slash);
    pattern = full.substr(slash + 1);
  }
  io_.find_device = d.device, io_.find_port = d.port, io_.find_next = 0;
  store(io_.find_dir, dir);
  store(io_.find_pattern, expand_pattern(pattern));
  return next_file(entry);
}

// nextfile(direntry): the next match after the last one, written as psx-spx's direntry: name
// (14h bytes), attribute, size, an unused pointer, the first sector, a reserved word.
u32 HleBios::next_file(u32 entry) {
  std::vector<DirEntry> entries = device_entries();
  const std::string pattern = load(io_.find_pattern);
  for (u32 i = io_.find_next; i < entries.size(); ++i) {
    const DirEntry& e = entries[i];
    if (!hle_name_matches(e.name, pattern)) continue;
    io_.find_next = i + 1;
    for (u32 k = 0; k < kPatternLength; ++k) poke8(entry + k, k < e.name.size() ? static_cast<u8>(e.name[k]) : 0);
    poke8(entry + kPatternLength - 1, 0);
    const u32 words[5] = {e.attr, e.size, 0, e.sector, 0};
    for (u32 k = 0; k < 5; ++k) poke32(entry + 0x14 + 4 * k, words[k]);
    return entry;
  }
  io_.find_next = static_cast<u32>(entries.size());
  return 0;
}

std::vector<HleBios::DirEntry> HleBios::device_entries() {
  if (io_.find_device == kDevCdrom) return cd_entries(load(io_.find_dir));
  if (io_.find_device == kDevCard) return card_entries(io_.find_port);
  return {};
}

// Returns v0 to the caller after the callbacks of the events the call delivered (mode 1000h)
// ran: their return sets v0, so a small kernel stub sets the call's own result and returns.
void HleBios::return_after_events(u32 v0) {
  if (callbacks_.empty()) {
    return_to_caller(v0);
    return;
  }
  if (!io_.result_stub) io_.result_stub = heap_alloc(kernel_heap_, 24);
  const u32 ra = cpu_.reg(kRegRa), s = io_.result_stub;
  const u32 code[6] = {0x3C020000 | v0 >> 16, 0x34420000 | (v0 & 0xFFFF),   // lui/ori v0
                       0x3C1F0000 | ra >> 16, 0x37FF0000 | (ra & 0xFFFF),   // lui/ori ra
                       0x03E00008, 0};                                      // jr ra; nop
  for (u32 i = 0; i < 6; ++i) poke32(s + 4 * i, code[i]);
  bus_.flush_icache();
  u32 f = callbacks_.front();
  callbacks_.erase(callbacks_.begin());
  call_guest(f, 0, {Resume::kCaller, s, 0});
}

}  // namespace psx
