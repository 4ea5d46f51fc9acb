/* Text output for PlayStation programs through the emulator debug console port 0x1F802080
   (DESIGN.md "Debug ports"), and the exit port 0x1F802082. Header-only. */
#ifndef PSX_TTY_H
#define PSX_TTY_H
#include <stdarg.h>
#include <stdint.h>

#define PSX_DEBUG_TTY (*(volatile uint8_t *)0xBF802080)
#define PSX_DEBUG_EXIT (*(volatile uint16_t *)0xBF802082)

static inline void tty_putc(char c) { PSX_DEBUG_TTY = (uint8_t)c; }

static inline void tty_puts(const char *s) {
  while (*s) tty_putc(*s++);
}

static inline void tty_put_unsigned(uint32_t v, unsigned base, int width, char pad) {
  char buf[12];
  int n = 0;
  do {
    unsigned d = v % base;
    buf[n++] = (char)(d < 10 ? '0' + d : 'A' + d - 10);
    v /= base;
  } while (v);
  while (n < width--) tty_putc(pad);
  while (n) tty_putc(buf[--n]);
}

/* printf subset: %d %u %x %X %s %c %%, with optional 0 flag and width (e.g. %08x). */
static inline void tty_vprintf(const char *fmt, va_list ap) {
  for (; *fmt; ++fmt) {
    if (*fmt != '%') {
      tty_putc(*fmt);
      continue;
    }
    ++fmt;
    char pad = ' ';
    int width = 0;
    if (*fmt == '0') pad = '0', ++fmt;
    while (*fmt >= '0' && *fmt <= '9') width = width * 10 + (*fmt++ - '0');
    switch (*fmt) {
      case 'd': {
        int32_t v = va_arg(ap, int32_t);
        if (v < 0) tty_putc('-'), v = -v, --width;
        tty_put_unsigned((uint32_t)v, 10, width, pad);
        break;
      }
      case 'u': tty_put_unsigned(va_arg(ap, uint32_t), 10, width, pad); break;
      case 'x':
      case 'X': tty_put_unsigned(va_arg(ap, uint32_t), 16, width, pad); break;
      case 's': tty_puts(va_arg(ap, const char *)); break;
      case 'c': tty_putc((char)va_arg(ap, int)); break;
      case '%': tty_putc('%'); break;
      default: tty_putc('?'); break;
    }
  }
}

static inline void tty_printf(const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  tty_vprintf(fmt, ap);
  va_end(ap);
}

/* Stops the emulator with `code` as the process exit status. */
static inline void psx_exit(uint16_t code) {
  PSX_DEBUG_EXIT = code;
  for (;;) {
  }
}

#endif
