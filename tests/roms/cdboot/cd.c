/* CD-ROM controller polling driver and ISO 9660 lookup (see cd.h). */
#include "cd.h"

#define CD_INDEX (*(volatile uint8_t *)0xBF801800)
#define CD_REG1 (*(volatile uint8_t *)0xBF801801)
#define CD_REG2 (*(volatile uint8_t *)0xBF801802)
#define CD_REG3 (*(volatile uint8_t *)0xBF801803)
#define I_STAT (*(volatile uint32_t *)0xBF801070)

/* Status register bit 5: the response FIFO is not empty. */
#define CD_STATUS_RSLRRDY 0x20
/* Request register bit 7 (BFRD): move the buffered sector into the data FIFO. */
#define CD_REQUEST_BFRD 0x80
/* Setmode bit 7: double speed; bit 5 clear: 0x800-byte data sectors. */
#define CD_MODE_DOUBLE_SPEED 0x80
/* Polls before giving up: far longer than the slowest answer used here (Init's second response
   after spinning the motor up, about a quarter of a second). */
#define CD_SPIN_LIMIT 20000000u

uint8_t cd_response[16];
int cd_response_len;

static uint8_t dir_sector[CD_SECTOR_SIZE];

/* Waits for the next interrupt and reads its response; returns INT1..INT5, or 0 on time-out.
   The interrupt stays pending until cd_ack(). */
static int cd_wait(void) {
  CD_INDEX = 1;
  for (uint32_t spin = 0; (CD_REG3 & 7) == 0; ++spin)
    if (spin > CD_SPIN_LIMIT) return 0;
  int type = CD_REG3 & 7;
  cd_response_len = 0;
  while ((CD_INDEX & CD_STATUS_RSLRRDY) && cd_response_len < 16) cd_response[cd_response_len++] = CD_REG1;
  return type;
}

/* Acknowledges the CD-ROM interrupt (flag register, index 1) and its I_STAT bit 2. */
static void cd_ack(void) {
  CD_INDEX = 1;
  CD_REG3 = 0x1F;
  I_STAT = ~(1u << 2);
}

static int cd_expect(int want) {
  int type = cd_wait();
  cd_ack();
  if (type == want) return CD_OK;
  if (type == 0) return CD_TIMEOUT;
  return type == 5 ? CD_ERROR : CD_UNEXPECTED;
}

static void cd_send(uint8_t cmd, const uint8_t *params, int n) {
  CD_INDEX = 0;
  for (int i = 0; i < n; ++i) CD_REG2 = params[i];
  CD_REG1 = cmd;
}

int cd_command(uint8_t cmd, const uint8_t *params, int n, int second) {
  cd_send(cmd, params, n);
  int r = cd_expect(3);
  if (r == CD_OK && second) r = cd_expect(2);
  return r;
}

int cd_init(void) {
  static const uint8_t mode[1] = {CD_MODE_DOUBLE_SPEED};
  int r = cd_command(0x0A, 0, 0, 1); /* Init */
  if (r == CD_OK) r = cd_command(0x0E, mode, 1, 0); /* Setmode */
  return r;
}

static uint8_t to_bcd(uint32_t v) { return (uint8_t)((v / 10) << 4 | (v % 10)); }

/* Interrupts Pause may see before its first response. That response comes after about 0xC4E1
   cycles, 1.5 ms (psx-spx "CDROM - Response Timings", the first response most commands share),
   in which a double-speed drive delivers at most one sector (150 a second, 6.7 ms apart) besides
   one already waiting: 16 is ample, and a drive still streaming after them is broken. */
#define CD_PAUSE_MAX_SECTORS 16

/* Pause: sectors (INT1) and the end of the disc (INT4, DataEnd, when the file read last ends
   where the disc does) that arrive before its first response are read past, a bounded number. */
static int cd_pause(void) {
  cd_send(0x09, 0, 0);
  int type, seen = 0;
  do {
    if (seen++ > CD_PAUSE_MAX_SECTORS) return CD_NO_PAUSE;
    type = cd_wait();
    cd_ack();
  } while (type == 1 || type == 4);
  if (type != 3) return type == 0 ? CD_TIMEOUT : CD_UNEXPECTED;
  return cd_expect(2);
}

int cd_read(uint32_t lba, void *dst, uint32_t bytes) {
  /* Setloc takes the absolute time in BCD: logical block 0 is 00:02:00 (150 sectors of pregap). */
  uint32_t abs = lba + 150;
  uint8_t loc[3] = {to_bcd(abs / 4500), to_bcd(abs / 75 % 60), to_bcd(abs % 75)};
  int r = cd_command(0x02, loc, 3, 0);
  if (r == CD_OK) r = cd_command(0x06, 0, 0, 0); /* ReadN */
  uint8_t *out = dst;
  while (r == CD_OK && bytes > 0) {
    int type = cd_wait();
    if (type != 1) {
      cd_ack();
      r = type == 0 ? CD_TIMEOUT : type == 5 ? CD_ERROR : CD_UNEXPECTED;
      break;
    }
    /* Take the data before acknowledging INT1, so the next sector cannot replace it. */
    uint32_t n = bytes < CD_SECTOR_SIZE ? bytes : CD_SECTOR_SIZE;
    CD_INDEX = 0;
    CD_REG3 = CD_REQUEST_BFRD;
    for (uint32_t i = 0; i < n; ++i) out[i] = CD_REG2;
    CD_REG3 = 0; /* drop what is left of the sector */
    cd_ack();
    out += n;
    bytes -= n;
  }
  int p = cd_pause();
  return r != CD_OK ? r : p;
}

static uint32_t le32(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static char upper(char c) { return c >= 'a' && c <= 'z' ? (char)(c - 32) : c; }

/* Does a directory record's name match one path component? A component without ';' matches
   any version. */
static int name_matches(const uint8_t *name, int name_len, const char *comp, int comp_len) {
  int i = 0;
  for (; i < comp_len; ++i)
    if (i >= name_len || upper((char)name[i]) != upper(comp[i])) return 0;
  return i == name_len || name[i] == ';';
}

/* Searches one directory (extent at dir_lba, dir_size bytes) for a component. */
static int find_in_dir(uint32_t dir_lba, uint32_t dir_size, const char *comp, int comp_len, uint32_t *lba,
                       uint32_t *size, int *is_dir) {
  for (uint32_t s = 0; s * CD_SECTOR_SIZE < dir_size; ++s) {
    int r = cd_read(dir_lba + s, dir_sector, CD_SECTOR_SIZE);
    if (r != CD_OK) return r;
    /* Records never cross a sector; a zero length byte ends the sector's records. */
    for (uint32_t off = 0; off < CD_SECTOR_SIZE && dir_sector[off] != 0; off += dir_sector[off]) {
      const uint8_t *rec = dir_sector + off;
      if (rec[0] < 34 || off + rec[0] > CD_SECTOR_SIZE || 33 + rec[32] > rec[0]) return CD_BAD_DIR;
      if (name_matches(rec + 33, rec[32], comp, comp_len)) {
        *lba = le32(rec + 2);
        *size = le32(rec + 10);
        *is_dir = (rec[25] & 2) != 0;
        return CD_OK;
      }
    }
  }
  return CD_NOT_FOUND;
}

int iso_find(const char *path, uint32_t *lba, uint32_t *size) {
  int r = cd_read(16, dir_sector, CD_SECTOR_SIZE);
  if (r != CD_OK) return r;
  if (dir_sector[0] != 1 || dir_sector[1] != 'C' || dir_sector[2] != 'D' || dir_sector[3] != '0' ||
      dir_sector[4] != '0' || dir_sector[5] != '1')
    return CD_NOT_ISO;
  /* The root directory's record is at byte 156 of the primary volume descriptor. */
  uint32_t at = le32(dir_sector + 156 + 2), len = le32(dir_sector + 156 + 10);
  int is_dir = 1;
  while (*path) {
    while (*path == '\\' || *path == '/') ++path;
    int n = 0;
    while (path[n] && path[n] != '\\' && path[n] != '/') ++n;
    if (n == 0) break;
    if (!is_dir) return CD_NOT_FOUND;
    r = find_in_dir(at, len, path, n, &at, &len, &is_dir);
    if (r != CD_OK) return r;
    path += n;
  }
  if (is_dir) return CD_NOT_FOUND;
  *lba = at;
  *size = len;
  return CD_OK;
}

const char *cd_error_text(int code) {
  switch (code) {
    case CD_OK: return "ok";
    case CD_TIMEOUT: return "the CD-ROM controller did not answer";
    case CD_ERROR: return "the CD-ROM controller reported an error (INT5)";
    case CD_UNEXPECTED: return "unexpected CD-ROM interrupt";
    case CD_NOT_ISO: return "no ISO 9660 primary volume descriptor at sector 16";
    case CD_BAD_DIR: return "malformed ISO 9660 directory record";
    case CD_NOT_FOUND: return "file not found";
    case CD_NO_PAUSE: return "the drive kept sending sectors after Pause";
    default: return "unknown error";
  }
}
