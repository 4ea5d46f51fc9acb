/* The cdboot boot ROM's boot sequence: what a BIOS does to start a disc, without Sony code.
   Sets the GPU to 640x480 interlace and follows its fields through GPUSTAT as a BIOS shell does,
   initialises the CD-ROM drive, asks for the disc (GetID; with none it idles like the shell),
   reads SYSTEM.CNF from the ISO 9660 file system (psx-spx "CDROM File Formats": BOOT and STACK;
   PSX.EXE;1 when there is no SYSTEM.CNF), loads the PS-X EXE (psx-spx "CDROM File Formats, PS-X
   EXE": 0x800-byte header, text at its load address, BSS cleared), and enters it with SP/GP set.
   Progress and errors go to the dev-kit DUART TX (0x1F802023); an error stops the emulator
   through the debug exit port with code 3. */
#include <stdint.h>

#include "cd.h"

#define DUART_TX (*(volatile uint8_t *)0xBF802023)
#define DEBUG_EXIT (*(volatile uint16_t *)0xBF802082)
#define GP1 (*(volatile uint32_t *)0xBF801814)
#define GPUSTAT GP1

/* GPUSTAT bit 31 (ODE): the displayed line is odd (the field, in 480-line interlace; 0 in VBlank).
   Bit 13 (ODE2): the interlace field being drawn, the one not displayed (psx-spx "GPU Status
   Register"). */
#define GPUSTAT_ODE 0x80000000u
#define GPUSTAT_ODE2 0x00002000u
/* Rounds of the field handshake before the ROM goes on; each spans two fields. */
#define FIELD_SYNC_ROUNDS 4
/* GPUSTAT reads before giving up on a field change: about three seconds of emulated time, far
   longer than the two fields (1/30 s) one round takes. A real BIOS waits forever; this ROM stops
   with a message instead, so a test fails rather than hangs. */
#define FIELD_SPIN_LIMIT 500000u

/* SYSTEM.CNF's STACK when it gives none (psx-spx). */
#define DEFAULT_STACK 0x801FFF00u
/* Programs live in user RAM: above the kernel area, within the 2 MiB. */
#define USER_RAM_START 0x00010000u
#define RAM_END 0x00200000u
#define EXE_HEADER_SIZE 0x800u

void exe_jump(uint32_t pc, uint32_t gp, uint32_t sp);

static uint8_t cnf_text[CD_SECTOR_SIZE + 1];
static uint8_t exe_header[EXE_HEADER_SIZE];
static char boot_path[64];

static void out_str(const char *s) {
  while (*s) DUART_TX = (uint8_t)*s++;
}

static void out_hex(uint32_t v) {
  for (int shift = 28; shift >= 0; shift -= 4) DUART_TX = (uint8_t)"0123456789ABCDEF"[(v >> shift) & 15];
}

static void fail(const char *what, const char *why) {
  out_str("cdboot: ");
  out_str(what);
  out_str(": ");
  out_str(why);
  out_str("\n");
  DEBUG_EXIT = 3;
  for (;;) {
  }
}

static void check(int r, const char *what) {
  if (r != CD_OK) fail(what, cd_error_text(r));
}

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
static char upper(char c) { return c >= 'a' && c <= 'z' ? (char)(c - 32) : c; }

static int parse_hex(const char *s, uint32_t *out) {
  uint32_t v = 0;
  int n = 0;
  for (; n < 8; ++n) {
    char c = upper(s[n]);
    if (c >= '0' && c <= '9') v = v << 4 | (uint32_t)(c - '0');
    else if (c >= 'A' && c <= 'F') v = v << 4 | (uint32_t)(c - 'A' + 10);
    else break;
  }
  *out = v;
  return n > 0;
}

/* Copies BOOT's path without the "cdrom:" device prefix and without arguments after it. */
static void take_boot_path(const char *v) {
  static const char device[] = "CDROM:";
  int i = 0;
  while (device[i] && upper(v[i]) == device[i]) ++i;
  if (device[i] == 0) v += i;
  int n = 0;
  while (v[n] && !is_space(v[n]) && n < (int)sizeof boot_path - 1) boot_path[n] = v[n], ++n;
  boot_path[n] = 0;
}

/* "KEY = VALUE" lines; keys other than BOOT and STACK (TCB, EVENT) concern a kernel this ROM
   does not have. */
static void parse_system_cnf(char *text, uint32_t *stack) {
  char *line = text;
  while (*line) {
    char *end = line;
    while (*end && *end != '\n') ++end;
    char *eq = line;
    while (eq < end && *eq != '=') ++eq;
    char *key = line;
    while (key < eq && is_space(*key)) ++key;
    char *key_end = eq;
    while (key_end > key && is_space(key_end[-1])) --key_end;
    char *value = eq + 1;
    while (value < end && is_space(*value)) ++value;
    char saved = *end;
    *end = 0;
    int key_len = (int)(key_end - key);
    if (eq < end && key_len == 4 && upper(key[0]) == 'B' && upper(key[1]) == 'O' && upper(key[2]) == 'O' &&
        upper(key[3]) == 'T')
      take_boot_path(value);
    else if (eq < end && key_len == 5 && upper(key[0]) == 'S' && upper(key[1]) == 'T' && upper(key[2]) == 'A' &&
             upper(key[3]) == 'C' && upper(key[4]) == 'K' && !parse_hex(value, stack))
      fail("SYSTEM.CNF", "STACK is not a hexadecimal number");
    *end = saved;
    line = *end ? end + 1 : end;
  }
}

static uint32_t le32(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static int in_user_ram(uint32_t addr, uint32_t size) {
  uint32_t phys = addr & 0x1FFFFFFFu;
  return phys >= USER_RAM_START && phys <= RAM_END && size <= RAM_END - phys;
}

static void load_and_run(uint32_t lba, uint32_t size, uint32_t stack) {
  if (size < EXE_HEADER_SIZE) fail(boot_path, "shorter than a PS-X EXE header");
  check(cd_read(lba, exe_header, EXE_HEADER_SIZE), boot_path);
  static const char magic[8] = "PS-X EXE";
  for (int i = 0; i < 8; ++i)
    if (exe_header[i] != (uint8_t)magic[i]) fail(boot_path, "not a PS-X EXE (no 'PS-X EXE' header)");
  uint32_t pc = le32(exe_header + 0x10), gp = le32(exe_header + 0x14);
  uint32_t text = le32(exe_header + 0x18), text_size = le32(exe_header + 0x1C);
  uint32_t bss = le32(exe_header + 0x28), bss_size = le32(exe_header + 0x2C);
  if (text_size > size - EXE_HEADER_SIZE) fail(boot_path, "text size runs past the end of the file");
  if (!in_user_ram(text, text_size)) fail(boot_path, "text outside user RAM (0x80010000-0x801FFFFF)");
  if (bss_size && !in_user_ram(bss, bss_size)) fail(boot_path, "BSS outside user RAM (0x80010000-0x801FFFFF)");
  out_str("cdboot: loading ");
  out_str(boot_path);
  out_str(" text ");
  out_hex(text);
  out_str("+");
  out_hex(text_size);
  out_str(" entry ");
  out_hex(pc);
  out_str(" stack ");
  out_hex(stack);
  out_str("\n");
  /* The text follows the header sector in the file; it goes straight to its load address. */
  check(cd_read(lba + EXE_HEADER_SIZE / CD_SECTOR_SIZE, (void *)(text | 0x80000000u), text_size), boot_path);
  for (uint32_t i = 0; i < bss_size; ++i) ((volatile uint8_t *)(bss | 0x80000000u))[i] = 0;
  exe_jump(pc, gp, stack);
}

/* Waits until GPUSTAT's bits 31 and 13 read `want` (their other bits masked off). */
static void wait_field(uint32_t want) {
  for (uint32_t spin = 0; (GPUSTAT & (GPUSTAT_ODE | GPUSTAT_ODE2)) != want; ++spin)
    if (spin > FIELD_SPIN_LIMIT) fail("GPU", "GPUSTAT bits 31/13 never showed the interlace fields");
}

/* One frame of a BIOS shell's field handshake: the odd field displayed while the even one is drawn
   (31 = 1, 13 = 0), then the even one displayed while the odd one is drawn (31 = 0, 13 = 1). If
   bit 13 followed the displayed field instead, the first state would never come. */
static void follow_fields(void) {
  wait_field(GPUSTAT_ODE);
  wait_field(GPUSTAT_ODE2);
}

/* GP1(00h) reset, then GP1(08h) 640x480, NTSC, 15-bit, vertical interlace (bit 5), as a BIOS shell
   sets the display up, and a few frames of its field handshake. */
static void gpu_init_interlaced(void) {
  GP1 = 0x00000000;
  GP1 = 0x08000027;
  for (int i = 0; i < FIELD_SYNC_ROUNDS; ++i) follow_fields();
  out_str("cdboot: GPU in 480-line interlace, fields followed\n");
}

/* GetID (psx-spx "CDROM Commands"): INT2 for a data disc, INT5 with flag bit 6
   ("missing disk") in its second byte when the drive is empty. */
static int disc_present(void) {
  int r = cd_command(0x1A, 0, 0, 1);
  if (r == CD_ERROR && cd_response_len >= 2 && (cd_response[1] & 0x40)) return 0;
  check(r, "GetID");
  return 1;
}

void rom_main(void) {
  out_str("cdboot: psxrl disc boot ROM\n");
  gpu_init_interlaced();
  check(cd_init(), "drive init");
  if (!disc_present()) {
    /* What a BIOS shows without a disc is its shell; this one only keeps following the fields. */
    out_str("cdboot: no disc: shell idle\n");
    for (;;) follow_fields();
  }
  uint32_t lba, size, stack = DEFAULT_STACK;
  int r = iso_find("SYSTEM.CNF;1", &lba, &size);
  if (r == CD_OK) {
    if (size > CD_SECTOR_SIZE) size = CD_SECTOR_SIZE;
    check(cd_read(lba, cnf_text, size), "SYSTEM.CNF");
    cnf_text[size] = 0;
    parse_system_cnf((char *)cnf_text, &stack);
    if (!boot_path[0]) fail("SYSTEM.CNF", "no BOOT line");
    out_str("cdboot: SYSTEM.CNF BOOT=");
    out_str(boot_path);
    out_str("\n");
  } else if (r == CD_NOT_FOUND) {
    take_boot_path("PSX.EXE;1");
  } else {
    check(r, "SYSTEM.CNF");
  }
  check(iso_find(boot_path, &lba, &size), boot_path);
  load_and_run(lba, size, stack);
}
