// psxexe: packs a statically linked little-endian MIPS ELF into a PS-X EXE. Only PT_LOAD segments
// are kept (the linker may add a GNU_STACK header at address 0); the loaded bytes become the text
// section at file offset 0x800, memory past the file bytes of the last segment becomes the BSS.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <stdexcept>
#include <vector>

#include "core/atomic_file.h"

namespace {

uint32_t rd32(const std::vector<uint8_t>& b, size_t o) {
  return b[o] | b[o + 1] << 8 | b[o + 2] << 16 | uint32_t(b[o + 3]) << 24;
}
uint16_t rd16(const std::vector<uint8_t>& b, size_t o) { return uint16_t(b[o] | b[o + 1] << 8); }
void wr32(std::vector<uint8_t>& b, size_t o, uint32_t v) {
  for (int i = 0; i < 4; ++i) b[o + i] = uint8_t(v >> (8 * i));
}

int fail(const std::string& file, const std::string& msg) {
  std::fprintf(stderr, "psxexe: %s: %s\n", file.c_str(), msg.c_str());
  return 2;
}

struct Segment {
  uint32_t offset, vaddr, filesz, memsz;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: psxexe INPUT.elf OUTPUT.exe\n");
    return 1;
  }
  std::string in = argv[1], out = argv[2];
  std::ifstream f(in, std::ios::binary);
  if (!f) return fail(in, "cannot open");
  std::vector<uint8_t> elf((std::istreambuf_iterator<char>(f)), {});
  if (elf.size() < 52 || std::memcmp(elf.data(), "\x7F" "ELF", 4) != 0) return fail(in, "offset 0: not an ELF file");
  if (elf[4] != 1 || elf[5] != 1) return fail(in, "offset 4: expected a 32-bit little-endian ELF");
  if (rd16(elf, 18) != 8) return fail(in, "offset 18: expected machine 8 (MIPS)");
  uint32_t entry = rd32(elf, 24), phoff = rd32(elf, 28);
  uint16_t phentsize = rd16(elf, 42), phnum = rd16(elf, 44);
  if (phoff + uint64_t(phnum) * phentsize > elf.size()) return fail(in, "program headers run past the end of the file");

  std::vector<Segment> segs;
  for (uint16_t i = 0; i < phnum; ++i) {
    size_t o = phoff + size_t(i) * phentsize;
    if (rd32(elf, o) != 1 || rd32(elf, o + 20) == 0) continue;  // PT_LOAD with memory only
    Segment s{rd32(elf, o + 4), rd32(elf, o + 8), rd32(elf, o + 16), rd32(elf, o + 20)};
    if (uint64_t(s.offset) + s.filesz > elf.size()) return fail(in, "segment " + std::to_string(i) + " runs past the end of the file");
    segs.push_back(s);
  }
  if (segs.empty()) return fail(in, "no loadable segments");

  uint32_t lo = UINT32_MAX, file_hi = 0, mem_hi = 0;
  for (const Segment& s : segs) {
    lo = std::min(lo, s.vaddr);
    file_hi = std::max(file_hi, s.vaddr + s.filesz);
    mem_hi = std::max(mem_hi, s.vaddr + s.memsz);
  }
  uint32_t text_size = (file_hi - lo + 0x7FF) & ~0x7FFu;
  std::vector<uint8_t> exe(0x800 + text_size, 0);
  for (const Segment& s : segs)
    std::memcpy(&exe[0x800 + (s.vaddr - lo)], &elf[s.offset], s.filesz);

  std::memcpy(exe.data(), "PS-X EXE", 8);
  wr32(exe, 0x10, entry);
  wr32(exe, 0x14, 0);          // gp: programs are built with -G0
  wr32(exe, 0x18, lo);         // text load address
  wr32(exe, 0x1C, text_size);  // text size, a multiple of 2 KiB
  uint32_t bss_start = (file_hi + 3) & ~3u;
  if (mem_hi > bss_start) {
    wr32(exe, 0x28, bss_start);
    wr32(exe, 0x2C, (mem_hi - bss_start + 3) & ~3u);
  }
  wr32(exe, 0x30, 0x801FFFF0);  // initial stack
  const char* marker = "Sony Computer Entertainment Inc. for North America area";
  std::memcpy(&exe[0x4C], marker, std::strlen(marker));

  try {
    psx::write_file_atomically(out, exe.data(), exe.size());
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "psxexe: %s\n", e.what());
    return 2;
  }
  return 0;
}
