/* The HLE kernel's C library calls of table A0h, made through the A0h vector as SDK code makes
   them. Expected values follow the C standard and are worked out by hand in the comments. */
#include "bios_calls.h"
#include "psx/test.h"

static char buf[64];

static int sign(int v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

int main(void) {
  /* strcpy/strcat/strncat: "ab" + "cd" = "abcd" (4 chars); strncat adds at most 2 of "efgh". */
  CHECK_EQ("strcpy returns dst", (uint32_t)bios_strcpy(buf, "ab"), (uint32_t)buf);
  CHECK_EQ("strcat returns dst", (uint32_t)bios_strcat(buf, "cd"), (uint32_t)buf);
  CHECK_EQ("strlen(abcd)", bios_strlen(buf), 4);
  bios_strncat(buf, "efgh", 2);
  CHECK_EQ("strncat length", bios_strlen(buf), 6);
  CHECK_EQ("strncat last", buf[5], 'f');
  /* strcmp: 'b' (62h) < 'c' (63h); a prefix compares less; equal strings give 0. */
  CHECK_EQ("strcmp less", sign(bios_strcmp("abc", "acb")), -1);
  CHECK_EQ("strcmp greater", sign(bios_strcmp("b", "abc")), 1);
  CHECK_EQ("strcmp prefix", sign(bios_strcmp("ab", "abc")), -1);
  CHECK_EQ("strcmp equal", bios_strcmp("same", "same"), 0);
  CHECK_EQ("strcmp unsigned bytes", sign(bios_strcmp("\x80", "\x01")), 1);
  CHECK_EQ("strncmp first 3 equal", bios_strncmp("abcX", "abcY", 3), 0);
  CHECK_EQ("strncmp 4th differs", sign(bios_strncmp("abcX", "abcY", 4)), -1);
  /* strncpy pads with NULs up to n and does not terminate when src is longer. */
  bios_memset(buf, 'z', 8);
  bios_strncpy(buf, "hi", 5);
  CHECK_EQ("strncpy pads", buf[0] == 'h' && buf[1] == 'i' && !buf[2] && !buf[3] && !buf[4] && buf[5] == 'z', 1);
  bios_strncpy(buf, "abcdef", 3);
  CHECK_EQ("strncpy truncates", buf[2] == 'c' && buf[3] == 0, 1);
  /* Searching in "hello world": 'o' first at 4, last at 7; 'z' absent. */
  const char *hw = "hello world";
  CHECK_EQ("strchr", (uint32_t)bios_strchr(hw, 'o'), (uint32_t)(hw + 4));
  CHECK_EQ("strrchr", (uint32_t)bios_strrchr(hw, 'o'), (uint32_t)(hw + 7));
  CHECK_EQ("strchr absent", (uint32_t)bios_strchr(hw, 'z'), 0);
  CHECK_EQ("strchr NUL finds the end", (uint32_t)bios_strchr(hw, 0), (uint32_t)(hw + 11));
  CHECK_EQ("strstr", (uint32_t)bios_strstr(hw, "wor"), (uint32_t)(hw + 6));
  CHECK_EQ("strstr absent", (uint32_t)bios_strstr(hw, "word"), 0);
  CHECK_EQ("strpbrk", (uint32_t)bios_strpbrk(hw, "wr"), (uint32_t)(hw + 6));
  CHECK_EQ("strspn", bios_strspn("aabbcx", "ab"), 4);
  CHECK_EQ("strcspn", bios_strcspn("hello", "lo"), 2);
  /* strtok splits "a,,bc;d" on ",;" into "a", "bc", "d", then NULL. */
  bios_strcpy(buf, "a,,bc;d");
  char *t1 = bios_strtok(buf, ",;");
  char *t2 = bios_strtok(0, ",;");
  char *t3 = bios_strtok(0, ",;");
  CHECK_EQ("strtok 1", (uint32_t)t1, (uint32_t)buf);
  CHECK_EQ("strtok 1 ends", buf[1], 0);
  CHECK_EQ("strtok 2", (uint32_t)t2, (uint32_t)(buf + 3));
  CHECK_EQ("strtok 3", (uint32_t)t3, (uint32_t)(buf + 6));
  CHECK_EQ("strtok end", (uint32_t)bios_strtok(0, ",;"), 0);
  /* ctype */
  CHECK_EQ("toupper a", bios_toupper('a'), 'A');
  CHECK_EQ("toupper 1", bios_toupper('1'), '1');
  CHECK_EQ("tolower Z", bios_tolower('Z'), 'z');
  /* Number conversion: 0x7F = 127, 017 (octal) = 15, " -42" = -42, "12ab" stops at 'a'. */
  char *end;
  CHECK_EQ("atoi", bios_atoi(" -42"), (uint32_t)-42);
  CHECK_EQ("atoi stops", bios_atoi("12ab"), 12);
  CHECK_EQ("strtol base 16", bios_strtol("0x7F", &end, 16), 127);
  CHECK_EQ("strtol base 0 hex", bios_strtol("0x7F", &end, 0), 127);
  CHECK_EQ("strtol base 0 octal", bios_strtol("017", &end, 0), 15);
  CHECK_EQ("strtol base 2", bios_strtol("1011z", &end, 2), 11);
  CHECK_EQ("strtol end", *end, 'z');
  CHECK_EQ("abs", bios_abs(-5), 5);
  CHECK_EQ("abs positive", bios_abs(7), 7);
  /* Memory functions. memmove with overlap: "123456" moved right by 2 over 4 bytes = "121234". */
  bios_strcpy(buf, "123456");
  bios_memmove(buf + 2, buf, 4);
  CHECK_EQ("memmove overlap", bios_strcmp(buf, "121234"), 0);
  bios_strcpy(buf, "123456");
  bios_memmove(buf, buf + 2, 4);
  CHECK_EQ("memmove left", bios_strcmp(buf, "345656"), 0);
  bios_bcopy("xy", buf, 2);
  CHECK_EQ("bcopy (src, dst)", buf[0] == 'x' && buf[1] == 'y', 1);
  bios_bzero(buf, 3);
  CHECK_EQ("bzero", buf[0] == 0 && buf[2] == 0 && buf[3] == '6', 1);
  CHECK_EQ("memcmp equal", bios_memcmp("ab\0c", "ab\0c", 4), 0);
  CHECK_EQ("memcmp past NUL", sign(bios_memcmp("ab\0c", "ab\0d", 4)), -1);
  const char *m = "abcabc";
  CHECK_EQ("memchr", (uint32_t)bios_memchr(m, 'c', 6), (uint32_t)(m + 2));
  CHECK_EQ("memchr limit", (uint32_t)bios_memchr(m, 'c', 2), 0);
  /* rand is the C standard's example generator: next = next * 1103515245 + 12345, result
     (next / 65536) % 32768. From seed 1: 1103527590 / 65536 = 16838. Next: 1103527590 *
     1103515245 + 12345 mod 2^32 = 0x967EB0E7; (that / 65536) % 32768 = 5758. */
  bios_srand(1);
  CHECK_EQ("rand 1", bios_rand(), 16838);
  CHECK_EQ("rand 2", bios_rand(), 5758);
  /* setjmp returns 0, then longjmp's value when jumped to. */
  static uint32_t jb[12];
  static volatile int jumps;
  int r = bios_setjmp(jb);
  if (r == 0) {
    ++jumps;
    bios_longjmp(jb, 7);
  }
  CHECK_EQ("longjmp value", r, 7);
  CHECK_EQ("setjmp once", jumps, 1);
  return test_done("bios_string");
}
