/* Prototypes of the stubs in bios_stdlib_calls.S (psx-spx "BIOS Function Summary"). atof and
   strtod return a double in COP1's f0 on the BIOS (compiled for a COP1 the PlayStation lacks), so
   nothing comes back here: they are declared void. */
#ifndef BIOS_STDLIB_CALLS_H
#define BIOS_STDLIB_CALLS_H
#include <stdint.h>

typedef int (*bios_compare)(const void *a, const void *b);

void bios_exit(int code);
void bios_atof(const char *s);
void bios_qsort(void *base, uint32_t nel, uint32_t width, bios_compare cmp);
void bios_strtod(const char *s, char **end);
void *bios_lsearch(const void *key, const void *base, uint32_t nel, uint32_t width, bios_compare cmp);
void *bios_bsearch(const void *key, const void *base, uint32_t nel, uint32_t width, bios_compare cmp);
void bios__exit(int code);
void bios_exit_b0(int code);

#endif
