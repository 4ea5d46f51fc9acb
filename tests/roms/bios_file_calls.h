/* Prototypes of the file, CD-ROM and memory card call stubs in bios_file_calls.S (psx-spx "BIOS
   File Functions", "BIOS CDROM Functions", "BIOS Memory Card Functions"). */
#ifndef BIOS_FILE_CALLS_H
#define BIOS_FILE_CALLS_H
#include <stdint.h>

/* firstfile2/nextfile's direntry (psx-spx "firstfile2"). */
struct dir_entry {
  char name[20];
  uint32_t attr, size, next, sector, reserved;
};

int32_t file_open(const char *path, uint32_t mode);
int32_t file_lseek(int32_t fd, int32_t offset, uint32_t whence);
int32_t file_read(int32_t fd, void *dst, uint32_t len);
int32_t file_write(int32_t fd, const void *src, uint32_t len);
int32_t file_close(int32_t fd);
int32_t file_getc(int32_t fd);
int32_t file_putc(int c, int32_t fd);
int32_t tty_getchar(void);
int32_t b_open(const char *path, uint32_t mode);
int32_t b_read(int32_t fd, void *dst, uint32_t len);
int32_t b_close(int32_t fd);
int32_t file_cd(const char *path);
struct dir_entry *first_file(const char *path, struct dir_entry *e);
struct dir_entry *next_file(struct dir_entry *e);
int32_t file_erase(const char *path);
uint32_t get_errno(void);
char *tty_gets(char *dst);
char *b_gets(char *dst);
int32_t file_format(const char *device);
int32_t file_rename(const char *from, const char *to);
int32_t file_undelete(const char *path);
void print_devices(void);
uint32_t get_error(int32_t fd);

int32_t cd_init(void);
int32_t cd_remove(void);
int32_t cd_get_lbn(const char *name);
int32_t cd_read_sector(uint32_t count, uint32_t sector, void *dst);
int32_t cd_get_status(void);

int32_t init_card(int pad_enable);
int32_t start_card(void);
int32_t stop_card(void);
int32_t bu_init(void);
int32_t card_info(uint32_t port);
int32_t card_load(uint32_t port);
int32_t card_auto(int flag);
int32_t card_write_test(uint32_t port);
int32_t card_write(uint32_t port, uint32_t sector, const void *src);
int32_t card_read(uint32_t port, uint32_t sector, void *dst);
int32_t new_card(void);
int32_t card_status(uint32_t slot);
int32_t card_wait(uint32_t slot);
uint32_t card_chan(void);
void bufs_cb_0(void);
void bufs_cb_4(void);
void set_card_find_mode(uint32_t mode);
uint32_t get_card_find_mode(void);

#define O_READ 0x0001
#define O_WRITE 0x0002
#define O_CREAT 0x0200
#define O_BLOCKS(n) ((uint32_t)(n) << 16)
#endif
