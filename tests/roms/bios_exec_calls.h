/* Prototypes of the executable and miscellaneous kernel call stubs in bios_exec_calls.S (psx-spx
   "BIOS File Execute and Flush Cache", "BIOS CDROM Functions", "BIOS Internal Boot Functions"). */
#ifndef BIOS_EXEC_CALLS_H
#define BIOS_EXEC_CALLS_H
#include <stdint.h>

/* LoadTest/Load's headerbuf: bytes 10h-4Bh of the PS-X EXE header, the last five words where
   Exec keeps the caller's registers (psx-spx "CDROM File Formats: PS-X EXE"). */
struct exec_header {
  uint32_t pc0, gp0, t_addr, t_size, d_addr, d_size, b_addr, b_size, s_addr, s_size;
  uint32_t sp, fp, gp, ra, s0;
};

uint32_t load_test(const char *path, struct exec_header *h);
int32_t load_exe(const char *path, struct exec_header *h);
int32_t exec_exe(struct exec_header *h, uint32_t param1, uint32_t param2);
void load_exec(const char *path, uint32_t stack_base, uint32_t stack_offset);
void warm_boot(void);
int32_t a0_return_zero_57(uint32_t a0);
int32_t c0_return_zero_0e(uint32_t a0);
int32_t cd_async_seekl(const uint8_t *msf);
int32_t cd_async_get_status(uint8_t *dst);
int32_t cd_async_read_sector(uint32_t count, void *dst, uint32_t mode);
int32_t cd_async_set_mode(uint32_t mode);
void set_mem(uint32_t megabytes);
void install_exception_handlers(void);
void sys_init_memory(void *addr, uint32_t size);
#endif
