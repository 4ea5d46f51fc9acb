// HLE kernel: loading and starting executables (psx-spx "BIOS File Execute and Flush Cache",
// "CDROM File Formats: PS-X EXE"): LoadTest A(41h), Load A(42h), Exec A(43h), LoadExec A(51h)
// and the warm boot _boot A(A0h), plus the calls psx-spx lists as returning 0 with no effect.
// Executables come from the cdrom: device (hle_cdfs.cpp) and are checked as the console's own
// loader checks them (core/bios/exe.h): a file that is not a loadable PS-X EXE is refused with a
// message naming the file, the header offset and what was expected, where a BIOS would copy
// whatever the header says.
#include <algorithm>
#include <cctype>

#include "core/bios/hle_bios.h"
#include "core/bus.h"
#include "core/disc/disc_boot.h"
#include "core/input_error.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kC0 = 0xC0;
constexpr u32 kIMask = 0xBF801074;
constexpr u32 kRegV0 = 2, kRegA0 = 4, kRegA1 = 5, kRegA2 = 6, kRegS0 = 16;
constexpr u32 kRegGp = 28, kRegSp = 29, kRegFp = 30, kRegRa = 31;
// headerbuf: bytes 10h-4Bh of the EXE header; Exec keeps the caller's registers in the last five
// words (psx-spx "PS-X EXE": 38h-4Bh "reserved for A(43h)").
constexpr u32 kHeaderFrom = 0x10, kHeaderBytes = 0x3C;
constexpr u32 kPc = 0x00, kGp = 0x04, kBssAddr = 0x18, kBssSize = 0x1C, kStackBase = 0x20, kStackOffset = 0x24;
constexpr u32 kSavedSp = 0x28, kSavedFp = 0x2C, kSavedGp = 0x30, kSavedRa = 0x34, kSavedS0 = 0x38;

// LoadExec's copy of the name (psx-spx "LoadExec" part 1): the device as given, the rest in upper
// case, and ";1" when no version is given.
std::string load_exec_name(const std::string& name) {
  std::string out;
  size_t colon = name.find(':');
  size_t rest = colon == std::string::npos ? name.size() : colon;
  out = name.substr(0, rest);
  for (size_t i = rest; i < name.size(); ++i)
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])));
  if (out.find(';') == std::string::npos) out += ";1";
  return out;
}

bool cdrom_path(const std::string& path) {
  std::string device = path.substr(0, path.find(':'));
  for (char& c : device) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return path.find(':') != std::string::npos && device.rfind("cdrom", 0) == 0;
}
}  // namespace

bool HleBios::exec_call(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1), a2 = cpu_.reg(kRegA2);
  switch (fn) {
    // LoadTest and Load return 1, or 0 when the file cannot be loaded. psx-spx gives no result and
    // no Sony document was found; this is OpenBIOS's (pcsx-redux src/mips/openbios/kernel/
    // psxexe.c, loadExeHeader/loadExe), a reimplementation that follows Sony's kernel down to its
    // quirks (the 3Ch header bytes copied, LoadExec's 28-byte name buffer psx-spx also describes).
    case 0x41: return_to_caller(exe_load(a0, a1, false) ? 1 : 0); return true;
    case 0x42: return_to_caller(exe_load(a0, a1, true) ? 1 : 0); return true;
    case 0x43: exec(a0, a1, a2); return true;
    case 0x51: load_exec(read_string(a0), a1, a2); return true;
    case 0xA0: warm_boot(); return true;
    default: return false;
  }
}

// A whole executable from the disc, checked; false with a message naming the problem. `header`
// gets the header words LoadTest copies.
bool HleBios::read_exe(const std::string& path, PsxExe& exe, std::vector<u8>& header, std::string& error) {
  HleFile f;
  u32 err = cdrom_path(path) ? cd_open(path, f) : kENoDev;
  if (err) {
    error = path + ": " + (err == kENoDev ? "only cdrom: executables can be loaded" : "file not found");
    return false;
  }
  std::vector<u8> file;
  if (!cd_sectors(f.first, (f.size + 0x7FF) / 0x800, 0x800, file)) {
    error = path + ": the disc's sectors cannot be read";
    return false;
  }
  file.resize(f.size);
  try {
    exe = PsxExe::parse(file, path);
  } catch (const InputError& e) {
    error = e.what();
    return false;
  }
  header.assign(file.begin() + kHeaderFrom, file.begin() + kHeaderFrom + kHeaderBytes);
  return true;
}

// LoadTest/Load: the header words to headerbuf, and for Load the text to its address (then the
// i-cache is flushed, as Load calls FlushCache). False, with a log message, when it cannot load.
bool HleBios::exe_load(u32 path_addr, u32 headerbuf, bool body) {
  const std::string path = read_string(path_addr);
  PsxExe exe;
  std::vector<u8> header;
  std::string error;
  if (!read_exe(path, exe, header, error)) {
    if (on_log) on_log(std::string("HLE kernel: ") + (body ? "Load" : "LoadTest") + " refused " + error);
    return false;
  }
  for (u32 i = 0; i < kHeaderBytes; ++i) poke8(headerbuf + i, header[i]);
  if (body) copy_text(exe);
  return true;
}

// Clears a RAM range (Exec's memfill region); addresses outside RAM are left alone.
void HleBios::zero_fill(u32 addr, u32 size) {
  const u32 p = Bus::physical(addr);
  if (p >= Bus::kRamSize || !size) return;
  const u32 n = std::min(size, Bus::kRamSize - p);
  std::fill_n(bus_.ram() + p, n, u8{0});
  bus_.host_wrote_ram(p, n);
}

void HleBios::copy_text(const PsxExe& exe) {
  const u32 base = Bus::physical(exe.text_addr) & (Bus::kRamSize - 1);
  for (u32 i = 0; i < exe.text.size(); ++i) bus_.ram()[base + i] = exe.text[i];
  bus_.host_wrote_ram(base, static_cast<u32>(exe.text.size()));
  bus_.flush_icache();
}

// Exec(headerbuf, param1, param2): the caller's sp, fp, gp, ra and s0 go to headerbuf, the BSS is
// cleared, sp/fp set from the stack fields (kept when the base is 0), gp from the header, and
// the entry point called with param1/param2 in a0/a1. It returns to kExecReturn with s0 still
// pointing at headerbuf (s0 is preserved by every function, psx-spx "BIOS Function Summary"), and
// that code restores the registers and returns 1 to Exec's caller.
void HleBios::exec(u32 headerbuf, u32 param1, u32 param2) {
  const u32 saved[5] = {cpu_.reg(kRegSp), cpu_.reg(kRegFp), cpu_.reg(kRegGp), cpu_.reg(kRegRa), cpu_.reg(kRegS0)};
  for (u32 i = 0; i < 5; ++i) poke32(headerbuf + kSavedSp + 4 * i, saved[i]);
  zero_fill(peek32(headerbuf + kBssAddr), peek32(headerbuf + kBssSize));
  const u32 base = peek32(headerbuf + kStackBase);
  if (base) {
    cpu_.set_reg(kRegSp, base + peek32(headerbuf + kStackOffset));
    cpu_.set_reg(kRegFp, cpu_.reg(kRegSp));
  }
  cpu_.set_reg(kRegGp, peek32(headerbuf + kGp));
  cpu_.set_reg(kRegS0, headerbuf);
  cpu_.set_reg(kRegRa, kExecReturn);
  cpu_.set_reg(kRegA0, param1);
  cpu_.set_reg(kRegA1, param2);
  cpu_.set_pc(peek32(headerbuf + kPc));
}

// LoadExec(filename, stackbase, stackoffset): interrupts enabled (ExitCriticalSection), the file
// loaded and started with the given stack (sp unchanged when stackbase is 0) and parameters 1, 0.
// A BIOS then reloads the boot file when the program returns or cannot be loaded (psx-spx: that
// part is broken, "treats the first 4 characters of the exename as memory address"); here a
// return stops the console as a return from the first program does, and a file that cannot be
// loaded stops it with the reason.
void HleBios::load_exec(const std::string& name, u32 stack_base, u32 stack_offset) {
  const std::string path = load_exec_name(name);
  PsxExe exe;
  std::vector<u8> header;
  std::string error;
  if (!read_exe(path, exe, header, error)) {
    if (on_fatal) on_fatal("HLE kernel: LoadExec cannot start " + error);
    cpu_.stop();
    return;
  }
  cpu_.cop0().sr |= Cop0::kIP2 | Cop0::kIEc;
  copy_text(exe);
  start(exe, stack_base ? stack_base + stack_offset : cpu_.reg(kRegSp), 1, 0);
}

// _boot: the kernel set up again and the disc's boot file started as at power-on (psx-spx: it
// "resets the kernel and reboots from CDROM", with the boot file SYSTEM.CNF names).
void HleBios::warm_boot() {
  disc::Disc* d = disc_in_drive ? disc_in_drive() : nullptr;
  try {
    if (!d) throw disc::DiscError("no disc in the drive");
    disc::BootConfig config;
    PsxExe exe = disc::load_boot_exe(*d, config);
    install();
    io_write(kIMask, 0, 4);  // no interrupt source enabled, as at the first program's entry
    copy_text(exe);
    start(exe, exe.stack_base + exe.stack_offset, 0, 0);
  } catch (const std::exception& e) {
    if (on_fatal) on_fatal(std::string("HLE kernel: _boot cannot restart the disc: ") + e.what());
    cpu_.stop();
  }
}

// The BSS cleared, gp/sp/fp set, and the entry point called with a0/a1; a return stops the
// console (kExitStub), as a return from the first program does.
void HleBios::start(const PsxExe& exe, u32 sp, u32 param1, u32 param2) {
  zero_fill(exe.bss_addr, exe.bss_size);
  cpu_.set_reg(kRegGp, exe.gp);
  cpu_.set_reg(kRegSp, sp);
  cpu_.set_reg(kRegFp, sp);
  cpu_.set_reg(kRegRa, kExitStub);
  cpu_.set_reg(kRegA0, param1);
  cpu_.set_reg(kRegA1, param2);
  cpu_.set_reg(kRegV0, 0);
  cpu_.set_pc(exe.pc);
}

// The calls psx-spx lists as "No function. Simply returns with r2=00000000h": A(57h-5Ah, 73h-77h,
// 79h-7Bh, 7Dh, 7Fh-80h, 82h-8Fh, B0h-B1h, B3h) and C(0Eh-11h, 14h).
bool HleBios::null_call(u32 table, u32 fn) {
  bool none = false;
  if (table == kA0)
    none = (fn >= 0x57 && fn <= 0x5A) || (fn >= 0x73 && fn <= 0x77) || (fn >= 0x79 && fn <= 0x7B) || fn == 0x7D ||
           fn == 0x7F || fn == 0x80 || (fn >= 0x82 && fn <= 0x8F) || fn == 0xB0 || fn == 0xB1 || fn == 0xB3;
  if (table == kC0) none = (fn >= 0x0E && fn <= 0x11) || fn == 0x14;
  if (none) return_to_caller(0);
  return none;
}

}  // namespace psx
