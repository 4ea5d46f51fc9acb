// What the BIOS's disc boot does before it starts a game (psx-spx "BIOS CDROM Boot"): read
// SYSTEM.CNF from the ISO 9660 root (BOOT = executable path, TCB/EVENT counts, STACK top), fall
// back to cdrom:\PSX.EXE;1 when it is absent, and load the boot executable. The HLE fast boot
// calls read_boot_config and hands the EXE to the kernel's loader with these settings.
#pragma once
#include <string>
#include <vector>

#include "core/bios/exe.h"
#include "core/disc/disc.h"

namespace psx::disc {

struct BootConfig {
  std::string boot_path = "cdrom:\\PSX.EXE;1";
  std::string boot_argument;  // text after the path on the BOOT line, if any
  u32 tcb = 4;                // thread control blocks
  u32 event = 0x10;           // event control blocks
  u32 stack = 0x801FFF00;     // initial stack pointer; replaces the EXE header's stack base
  std::vector<u8> exe;        // the PS-X EXE file as stored on the disc
};

// Parses SYSTEM.CNF text (KEY = VALUE lines, numbers in hex). Unknown keys are ignored, as the
// BIOS does; a malformed number throws DiscError naming `name` and the line.
BootConfig parse_system_cnf(const std::string& text, const std::string& name);

// Reads SYSTEM.CNF and the boot EXE from the disc. Throws DiscError when the disc has no ISO
// 9660 volume, the executable is missing, or it is not a PS-X EXE.
BootConfig read_boot_config(Disc& disc);

// The HLE fast boot's executable: the boot EXE parsed, with SYSTEM.CNF's STACK as its stack
// (the BIOS passes STACK to Exec(), overriding the header's stack fields). The kernel's TCB and
// EVENT counts are returned in `config` for a kernel that allocates those tables.
PsxExe load_boot_exe(Disc& disc, BootConfig& config);

}  // namespace psx::disc
