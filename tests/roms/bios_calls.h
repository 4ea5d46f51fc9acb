/* Prototypes of the BIOS call stubs in bios_calls.S (psx-spx "BIOS Function Summary"). */
#ifndef BIOS_CALLS_H
#define BIOS_CALLS_H
#include <stdint.h>

int32_t bios_strtol(const char *s, char **end, int base);
int32_t bios_abs(int32_t v);
int32_t bios_atoi(const char *s);
int bios_setjmp(uint32_t *buf);
void bios_longjmp(uint32_t *buf, int value);
char *bios_strcat(char *d, const char *s);
char *bios_strncat(char *d, const char *s, uint32_t n);
int bios_strcmp(const char *a, const char *b);
int bios_strncmp(const char *a, const char *b, uint32_t n);
char *bios_strcpy(char *d, const char *s);
char *bios_strncpy(char *d, const char *s, uint32_t n);
uint32_t bios_strlen(const char *s);
char *bios_strchr(const char *s, int c);
char *bios_strrchr(const char *s, int c);
char *bios_strpbrk(const char *s, const char *set);
uint32_t bios_strspn(const char *s, const char *set);
uint32_t bios_strcspn(const char *s, const char *set);
char *bios_strtok(char *s, const char *delim);
char *bios_strstr(const char *s, const char *needle);
int bios_toupper(int c);
int bios_tolower(int c);
void bios_bcopy(const void *s, void *d, uint32_t n);
void bios_bzero(void *d, uint32_t n);
void *bios_memcpy(void *d, const void *s, uint32_t n);
void *bios_memset(void *d, int c, uint32_t n);
void bios_flush_cache(void);
void *bios_memmove(void *d, const void *s, uint32_t n);
int bios_memcmp(const void *a, const void *b, uint32_t n);
void *bios_memchr(const void *s, int c, uint32_t n);
int bios_rand(void);
void bios_srand(uint32_t seed);
void *bios_malloc(uint32_t n);
void bios_free(void *p);
void *bios_calloc(uint32_t count, uint32_t size);
void *bios_realloc(void *p, uint32_t n);
void bios_init_heap(void *base, uint32_t size);
uint32_t bios_get_system_info(uint32_t index);
void *alloc_kernel_memory(uint32_t n);
void free_kernel_memory(void *p);

int set_rcnt(uint32_t counter, uint32_t target, uint32_t flags);
int start_rcnt(uint32_t counter);
int stop_rcnt(uint32_t counter);
void deliver_event(uint32_t cls, uint32_t spec);
uint32_t open_event(uint32_t cls, uint32_t spec, uint32_t mode, void (*func)(void));
int close_event(uint32_t ev);
int wait_event(uint32_t ev);
int test_event(uint32_t ev);
int enable_event(uint32_t ev);
int disable_event(uint32_t ev);
void undeliver_event(uint32_t cls, uint32_t spec);
int init_pad(uint8_t *buf1, uint32_t size1, uint8_t *buf2, uint32_t size2);
int start_pad(void);
int stop_pad(void);
void return_from_exception(void);
uint32_t *reset_entry_int(void);
void hook_entry_int(const uint32_t *jmp_buf);
void change_clear_pad(int flag);
int sys_enq_int_rp(int priority, uint32_t *element);
int sys_deq_int_rp(int priority, uint32_t *element);
int change_clear_rcnt(int counter, int flag);
uint32_t open_th(void (*pc)(void), void *sp, void *gp);
int close_th(uint32_t thread);
int change_th(uint32_t thread);
int32_t krom2_raw_add(uint32_t sjis);
uint32_t *get_c0_table(void);
uint32_t *get_b0_table(void);
int enqueue_rcnt_irqs(int priority);
int enqueue_syscall_handler(int priority);
int init_def_int(int priority);
void set_irq_auto_ack(uint32_t irq, int flag);
uint32_t enter_critical_section(void);
void exit_critical_section(void);

#define I_STAT (*(volatile uint32_t *)0xBF801070)
#define I_MASK (*(volatile uint32_t *)0xBF801074)
#endif
