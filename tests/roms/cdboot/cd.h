/* A polling driver for the CD-ROM controller (psx-spx "CDROM Controller I/O Ports", "CDROM
   Commands") and ISO 9660 file lookup (ECMA-119 volume descriptor and directory records), shared
   by the cdboot boot ROM and the test program it boots. No interrupts are used: the interrupt
   flag register (index 1, register 3) is polled, as a BIOS's boot code may. */
#ifndef CDBOOT_CD_H
#define CDBOOT_CD_H
#include <stdint.h>

#define CD_SECTOR_SIZE 2048

enum {
  CD_OK = 0,
  CD_TIMEOUT = -1,    /* no interrupt arrived in time */
  CD_ERROR = -2,      /* the controller answered INT5 (cd_response holds stat and error code) */
  CD_UNEXPECTED = -3, /* an interrupt other than the one the command sequence expects */
  CD_NOT_ISO = -4,    /* sector 16 is not an ISO 9660 primary volume descriptor */
  CD_BAD_DIR = -5,    /* a directory record runs past its sector or is too short */
  CD_NOT_FOUND = -6,
  CD_NO_PAUSE = -7,   /* sectors kept arriving after Pause, with no response to it */
};

/* The last response read, and its length. */
extern uint8_t cd_response[16];
extern int cd_response_len;

/* Sends a command with parameters and waits for its first response (INT3), and for the second
   one (INT2) when `second` is set. */
int cd_command(uint8_t cmd, const uint8_t *params, int n, int second);
/* Init, then Setmode double speed with 0x800-byte data sectors. */
int cd_init(void);
/* Reads `bytes` bytes from logical block `lba` on (whole sectors, the last one in part) into dst
   with Setloc + ReadN, then pauses the drive. */
int cd_read(uint32_t lba, void *dst, uint32_t bytes);
/* Finds a file by path ("SYSTEM.CNF;1", "\DIR\FILE.EXE"; '\' or '/' separate directories, the
   ";1" version may be left out, letters are compared without case). */
int iso_find(const char *path, uint32_t *lba, uint32_t *size);
/* Text for a CD_* code. */
const char *cd_error_text(int code);

#endif
