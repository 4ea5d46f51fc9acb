/* Loading and starting executables (psx-spx "BIOS File Execute and Flush Cache", "A(A0h)
   _boot", "CDROM File Formats: PS-X EXE"), booted from a mkdisc disc as BOOT.EXE beside
   CHILD.EXE (bios_exec_child.c, linked at 0x80100000) and DATA.BIN (letters, no EXE).
   _boot first: the program patches an A0h table entry and warm-boots; started again it finds the
   kernel's entry back. LoadTest copies header bytes 10h-4Bh to headerbuf and returns 1 (as
   OpenBIOS: psx-spx gives no result), 0 when it cannot load the file; Load also copies the
   text (header word 1Ch bytes from file offset 800h) to its address (word 18h); Exec clears the
   BSS, sets sp/fp = stack base + offset, gp from the header, calls the entry with param1/param2 in
   a0/a1 and returns 1 with the caller's gp back. Last, LoadExec starts the child by a lower-case
   name without version (LoadExec upper-cases it and adds ";1"), which checks its entry state and
   ends the test with the parent's counts added to its own. */
#include "bios_calls.h"
#include "bios_exec_calls.h"
#include "bios_exec_shared.h"
#include "bios_file_calls.h"
#include "psx/test.h"

#define CHILD "cdrom:\\CHILD.EXE;1"
#define A_TABLE ((volatile uint32_t *)0x80000200)

static uint8_t file[16384];
static struct exec_header hdr;

static uint32_t le32(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static uint32_t gp_now(void) {
  uint32_t gp;
  __asm__ volatile("move %0, $gp" : "=r"(gp));
  return gp;
}

/* First start: remember the kernel's A0h entry 57h, patch it, and warm-boot (no return). */
static void boot_once(void) {
  if (SCRATCH[kPhase] == kPhaseBoot) return;
  SCRATCH[kPhase] = kPhaseBoot;
  SCRATCH[kTableEntry] = A_TABLE[0x57];
  A_TABLE[0x57] = 0x80000000;
  warm_boot();
  SCRATCH[kPhase] = 0;
}

static void load_calls(void) {
  int32_t fd = file_open(CHILD, O_READ);
  file_read(fd, file, 0x800);
  uint32_t size = 0x800 + le32(file + 0x1C); /* header + text size (a multiple of 800h) */
  CHECK_EQ("CHILD.EXE: header and text fit the buffer", size > 0x800 && size <= sizeof file, 1);
  file_read(fd, file + 0x800, size - 0x800);
  file_close(fd);
  CHECK_EQ("LoadTest: 1 (OpenBIOS's result; psx-spx gives none)", load_test(CHILD, &hdr), 1);
  CHECK_EQ("LoadTest: headerbuf = header bytes 10h-4Bh", bios_memcmp(&hdr, file + 0x10, 0x3C), 0);
  CHECK_EQ("LoadTest of a missing file", load_test("cdrom:\\NOSUCH.EXE;1", &hdr), 0);
  CHECK_EQ("LoadTest of a file that is no PS-X EXE", load_test("cdrom:\\DATA.BIN;1", &hdr), 0);
  CHECK_EQ("child's text address (its link address)", le32(file + 0x18), 0x80100000);
  bios_memset((void *)0x80100000, 0xAA, le32(file + 0x1C));
  CHECK_EQ("Load", load_exe(CHILD, &hdr), 1);
  CHECK_EQ("Load: the text in RAM", bios_memcmp((void *)hdr.t_addr, file + 0x800, hdr.t_size), 0);
  CHECK_EQ("Load: headerbuf", bios_memcmp(&hdr, file + 0x10, 0x3C), 0);
}

static void exec_call(void) {
  CHECK_EQ("the child has a BSS", hdr.b_size != 0, 1);
  bios_memset((void *)hdr.b_addr, 0xFF, hdr.b_size);
  hdr.s_addr = 0x801F0000;
  hdr.s_size = 0x100;
  hdr.gp0 = 0x80123450;
  SCRATCH[kPhase] = kPhaseExec;
  uint32_t gp = gp_now();
  CHECK_EQ("Exec returns 1", exec_exe(&hdr, 0x1234, 0x5678), 1);
  CHECK_EQ("Exec: the caller's gp back", gp_now(), gp);
  CHECK_EQ("Exec: param1 in a0", SCRATCH[kChildA0], 0x1234);
  CHECK_EQ("Exec: param2 in a1", SCRATCH[kChildA1], 0x5678);
  CHECK_EQ("Exec: sp = s_addr + s_size", SCRATCH[kChildSp], 0x801F0100);
  CHECK_EQ("Exec: gp = gp0", SCRATCH[kChildGp], 0x80123450);
  CHECK_EQ("Exec: BSS cleared", SCRATCH[kChildBss], 0);
  CHECK_EQ("Exec: headerbuf keeps the caller's gp", hdr.gp, gp);
}

int main(void) {
  boot_once();
  CHECK_EQ("_boot started the boot file again", SCRATCH[kPhase], kPhaseBoot);
  CHECK_EQ("_boot set up the kernel's A0h table again", A_TABLE[0x57], SCRATCH[kTableEntry]);
  load_calls();
  exec_call();
  SCRATCH[kFileGp] = le32(file + 0x14);
  SCRATCH[kPhase] = kPhaseLoadExec;
  SCRATCH[kParentChecks] = (uint32_t)test_checks;
  SCRATCH[kParentFailures] = (uint32_t)test_failures;
  load_exec("cdrom:\\child.exe", kLoadExecStack, kLoadExecOffset);
  CHECK_EQ("LoadExec does not return", 0, 1);
  return test_done("bios_exec");
}
