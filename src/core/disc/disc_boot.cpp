// SYSTEM.CNF parsing and boot-executable lookup for the HLE disc boot.
#include "core/disc/disc_boot.h"

#include <cstring>
#include <sstream>

#include "core/disc/iso9660.h"

namespace psx::disc {
namespace {

std::string trim(const std::string& s) {
  size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  size_t b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

u32 parse_hex(const std::string& v, const std::string& where) {
  if (v.empty() || v.size() > 8 || v.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
    throw DiscError(where + ": expected a hexadecimal number, found '" + v + "'");
  return static_cast<u32>(std::stoul(v, nullptr, 16));
}

constexpr u32 kMaxExeSize = 2 * 1024 * 1024;  // it must fit in main RAM

}  // namespace

BootConfig parse_system_cnf(const std::string& text, const std::string& name) {
  BootConfig cfg;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = trim(line.substr(0, eq));
    for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    std::string value = trim(line.substr(eq + 1));
    std::string where = name + ":" + std::to_string(line_no);
    if (key == "BOOT") {
      size_t sp = value.find_first_of(" \t");
      cfg.boot_path = value.substr(0, sp);
      cfg.boot_argument = sp == std::string::npos ? "" : trim(value.substr(sp));
      if (cfg.boot_path.empty()) throw DiscError(where + ": BOOT has no executable path");
    } else if (key == "TCB") {
      cfg.tcb = parse_hex(value, where);
    } else if (key == "EVENT") {
      cfg.event = parse_hex(value, where);
    } else if (key == "STACK") {
      cfg.stack = parse_hex(value, where);
    }
  }
  return cfg;
}

BootConfig read_boot_config(Disc& disc) {
  IsoFilesystem fs(disc);
  BootConfig cfg;
  if (auto cnf = fs.find("SYSTEM.CNF;1")) {
    std::vector<u8> text = fs.read(*cnf, 64 * 1024);
    cfg = parse_system_cnf(std::string(text.begin(), text.end()), disc.path() + ":SYSTEM.CNF");
  }
  auto exe = fs.find(cfg.boot_path);
  if (!exe || exe->directory)
    throw DiscError(disc.path() + ": boot executable '" + cfg.boot_path + "' not found on the disc");
  cfg.exe = fs.read(*exe, kMaxExeSize);
  if (cfg.exe.size() < 0x800 || std::memcmp(cfg.exe.data(), "PS-X EXE", 8) != 0)
    throw DiscError(disc.path() + ": '" + cfg.boot_path + "' is not a PS-X EXE (expected the 'PS-X EXE' header)");
  return cfg;
}

PsxExe load_boot_exe(Disc& disc, BootConfig& config) {
  config = read_boot_config(disc);
  PsxExe exe = PsxExe::parse(config.exe, disc.path() + ":" + config.boot_path);
  exe.stack_base = config.stack;
  exe.stack_offset = 0;
  return exe;
}

}  // namespace psx::disc
