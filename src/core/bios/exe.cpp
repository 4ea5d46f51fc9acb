// PS-X EXE header parsing and validation.
#include "core/bios/exe.h"

#include <cstring>

#include "core/bus.h"
#include "core/endian.h"
#include "core/input_error.h"

namespace psx {

namespace {
// A KUSEG/KSEG0/KSEG1 address range that lies inside the 2 MiB of main RAM (any mirror).
bool in_ram(u32 addr, u32 size) {
  u32 p = Bus::physical(addr);
  return p < Bus::kRamSize && size <= Bus::kRamSize - p;
}
}  // namespace

PsxExe PsxExe::parse(const std::vector<u8>& f, const std::string& name) {
  if (f.size() < kHeaderSize)
    throw InputError::at_offset(name, f.size(), "file ends inside the 2048-byte PS-X EXE header");
  if (std::memcmp(f.data(), "PS-X EXE", 8) != 0)
    throw InputError::at_offset(name, 0, "expected the magic \"PS-X EXE\"");
  auto word = [&](u32 off) { return load_le32(&f[off]); };
  PsxExe exe;
  exe.pc = word(0x10);
  exe.gp = word(0x14);
  exe.text_addr = word(0x18);
  exe.text_size = word(0x1C);
  exe.bss_addr = word(0x28);
  exe.bss_size = word(0x2C);
  exe.stack_base = word(0x30);
  exe.stack_offset = word(0x34);

  if (exe.text_size == 0 || exe.text_size % 0x800 != 0)
    throw InputError::at_offset(name, 0x1C, "text size " + std::to_string(exe.text_size) + " is not a nonzero multiple of 2048");
  if (!in_ram(exe.text_addr, exe.text_size))
    throw InputError::at_offset(name, 0x18, "text does not fit in RAM at its load address");
  if (f.size() < kHeaderSize + u64(exe.text_size))
    throw InputError::at_offset(name, f.size(), "file is shorter than header + text size (" +
                                                    std::to_string(kHeaderSize + u64(exe.text_size)) + " bytes)");
  if (exe.pc & 3) throw InputError::at_offset(name, 0x10, "entry point is not word aligned");
  if (!in_ram(exe.pc, 4)) throw InputError::at_offset(name, 0x10, "entry point is outside RAM");
  if (exe.bss_size && !in_ram(exe.bss_addr, exe.bss_size))
    throw InputError::at_offset(name, 0x28, "BSS does not fit in RAM");
  if (exe.stack_base && !in_ram(exe.stack_base + exe.stack_offset - 4, 4))
    throw InputError::at_offset(name, 0x30, "initial stack is outside RAM");
  exe.text.assign(f.begin() + kHeaderSize, f.begin() + kHeaderSize + exe.text_size);
  return exe;
}

}  // namespace psx
