/* The kernel's RAM as programs read and patch it (psx-spx "BIOS Memory Map", "BIOS Function
   Summary", "BIOS Event Functions", "BIOS Thread Functions", "BIOS Interrupt/Exception
   Handling"): the table of tables at 100h and the ExCB/PCB/TCB/EvCB blocks it points to, the
   A/B/C function tables (GetB0Table/GetC0Table, a patched entry, calls through an entry), the
   kernel set up again as psyqo does it (blocks cleared, C0h:01h/0Ch/00h), root counter 3
   events on VBlank, DefInt with SetIrqAutoAck, a BREAK resolved by an F0000010h event handler
   through the TCB, threads, FlushCache over rewritten code, and Krom2RawAdd's -1. */
#include "bios_calls.h"
#include "psx/test.h"

#define SPIN_LIMIT 20000000
/* Kernel words through KSEG0 (the tables hold KSEG0 pointers; OR-ing keeps them). */
#define KWORD(a) (*(volatile uint32_t *)(0x80000000u | (a)))

static void wait_for(volatile uint32_t *counter, uint32_t target) {
  for (uint32_t i = 0; *counter < target && i < SPIN_LIMIT; ++i) {
  }
}

/* 1. The table of tables: pointers and sizes (ExCB 4 x 8, PCB 4, TCB 4 x C0h, EvCB 16 x 1Ch). */
static void table_of_tables(void) {
  CHECK_EQ("ExCB size", KWORD(0x104), 0x20);
  CHECK_EQ("PCB size", KWORD(0x10C), 4);
  CHECK_EQ("TCB size", KWORD(0x114), 4 * 0xC0);
  CHECK_EQ("EvCB size", KWORD(0x124), 16 * 0x1C);
  CHECK_EQ("ExCB in kernel RAM", (KWORD(0x100) & 0x1FFFFFFF) < 0x10000, 1);
  CHECK_EQ("PCB points at TCB 0", KWORD(KWORD(0x108)), KWORD(0x110));
  CHECK_EQ("TCB 0 in use", KWORD(KWORD(0x110)), 0x4000);
  CHECK_EQ("TCB 1 free", KWORD(KWORD(0x110) + 0xC0), 0x1000);
}

/* 2. Function tables: a patched A0h entry is called through the vector and may chain to the
      entry it replaced; a B0h function called through its table entry works. */
typedef uint32_t (*strlen_fn)(const char *);
static strlen_fn old_strlen;
static uint32_t my_strlen(const char *s) { return old_strlen(s) + 100; }

static void function_tables(void) {
  CHECK_EQ("GetB0Table", (uint32_t)get_b0_table() & 0x1FFFFFFF, 0x874);
  CHECK_EQ("GetC0Table", (uint32_t)get_c0_table() & 0x1FFFFFFF, 0x674);
  volatile uint32_t *a_table = (volatile uint32_t *)0x80000200;
  old_strlen = (strlen_fn)a_table[0x1B];
  a_table[0x1B] = (uint32_t)my_strlen;
  CHECK_EQ("patched strlen chains to the old entry", bios_strlen("abc"), 103);
  a_table[0x1B] = (uint32_t)old_strlen;
  CHECK_EQ("restored strlen", bios_strlen("abc"), 3);
  uint32_t *(*b57)(void) = (uint32_t * (*)(void)) get_b0_table()[0x57];
  CHECK_EQ("B0h:57h through its table entry", (uint32_t)b57(), (uint32_t)get_b0_table());
}

/* 3. The chains and events live in the ExCB and EvCB blocks. */
static uint32_t element[4];

static void blocks(void) {
  uint32_t excb = KWORD(0x100), evcb = KWORD(0x120);
  uint32_t old_head = KWORD(excb);
  sys_enq_int_rp(0, element);
  CHECK_EQ("SysEnqIntRP links at the chain head", KWORD(excb), (uint32_t)element);
  CHECK_EQ("element's next is the old head", element[0], old_head);
  sys_deq_int_rp(0, element);
  CHECK_EQ("SysDeqIntRP unlinks", KWORD(excb), old_head);

  uint32_t ev = open_event(0xF0001234, 0x55, 0x2000, 0);
  uint32_t cb = evcb + (ev & 0xFFFF) * 0x1C;
  CHECK_EQ("event handle", ev >> 16, 0xF100);
  CHECK_EQ("EvCB class", KWORD(cb), 0xF0001234);
  CHECK_EQ("EvCB spec", KWORD(cb + 8), 0x55);
  CHECK_EQ("EvCB mode", KWORD(cb + 12), 0x2000);
  CHECK_EQ("EvCB opened disabled", KWORD(cb + 4), 0x1000);
  enable_event(ev);
  CHECK_EQ("EvCB enabled busy", KWORD(cb + 4), 0x2000);
  deliver_event(0xF0001234, 0x55);
  CHECK_EQ("EvCB delivered ready", KWORD(cb + 4), 0x4000);
  CHECK_EQ("TestEvent consumes", test_event(ev), 1);
  CHECK_EQ("EvCB busy again", KWORD(cb + 4), 0x2000);
  close_event(ev);
  CHECK_EQ("EvCB closed free", KWORD(cb + 4), 0);
}

/* 4. psyqo's start-up: clear ExCB and EvCB, re-enqueue the kernel's handlers, then a callback
      event on root counter 3 (VBlank) and, with its auto-acknowledge off, DefInt's VBlank event
      acknowledged by SetIrqAutoAck. */
static volatile uint32_t rcnt3_calls, defint_calls;
static void rcnt3_callback(void) { ++rcnt3_calls; }
static void defint_callback(void) { ++defint_calls; }

static void psyqo_setup(void) {
  enter_critical_section();
  for (uint32_t i = 0; i < KWORD(0x104); i += 4) KWORD(KWORD(0x100) + i) = 0;
  for (uint32_t i = 0; i < KWORD(0x124); i += 4) KWORD(KWORD(0x120) + i) = 0;
  reset_entry_int();
  enqueue_syscall_handler(0);
  init_def_int(3);
  enqueue_rcnt_irqs(1);
  CHECK_EQ("three chains set up again", KWORD(KWORD(0x100)) && KWORD(KWORD(0x100) + 8) && KWORD(KWORD(0x100) + 24), 1);
  uint32_t ev = open_event(0xF2000003, 2, 0x1000, rcnt3_callback);
  enable_event(ev);
  uint32_t ev2 = open_event(0xF0000001, 0x1000, 0x1000, defint_callback);
  enable_event(ev2);
  set_irq_auto_ack(0, 1);
  start_rcnt(3);
  CHECK_EQ("I_MASK VBlank after StartRCnt(3)", I_MASK & 1, 1);
  exit_critical_section();
  wait_for(&rcnt3_calls, 3);
  CHECK_EQ("root counter 3 events on VBlank", rcnt3_calls >= 3, 1);
  CHECK_EQ("DefInt saw no VBlank (root counter 3 acknowledged it)", defint_calls, 0);

  enter_critical_section();
  CHECK_EQ("ChangeClearRCnt(3, 0) returns on", change_clear_rcnt(3, 0), 1);
  exit_critical_section();
  wait_for(&defint_calls, 3);
  CHECK_EQ("DefInt delivers F0000001h when root counter 3 leaves VBlank", defint_calls >= 3, 1);
  enter_critical_section();
  change_clear_rcnt(3, 1);
  close_event(ev2);
  close_event(ev);
  stop_rcnt(3);
  exit_critical_section();
}

/* 5. A BREAK resolved as psyqo does: the F0000010h/1000h handler reads Cause and EPC from the
      current TCB, steps over the instruction and returns from the exception. */
static volatile uint32_t break_cause, break_code;
static void exception_callback(void) {
  uint32_t tcb = KWORD(KWORD(0x108));
  break_cause = KWORD(tcb + 0x98) & 0x3C;
  uint32_t epc = KWORD(tcb + 0x88);
  break_code = KWORD(epc) >> 6;
  KWORD(tcb + 0x88) = epc + 4;
  return_from_exception();
}

static void break_event(void) {
  uint32_t ev = open_event(0xF0000010, 0x1000, 0x1000, exception_callback);
  enable_event(ev);
  __asm__ volatile("break 0x123");
  CHECK_EQ("Cause in the TCB is Break", break_cause, 0x24);
  CHECK_EQ("BREAK code through the TCB's EPC", break_code, 0x123 << 10);
  close_event(ev);
}

/* 6. Threads: OpenTh takes TCB 1; ChangeTh runs it, and it changes back to thread 0. */
static uint8_t thread_stack[1024];
static volatile uint32_t thread_ran;
static void thread_main(void) {
  for (;;) {
    ++thread_ran;
    change_th(0xFF000000);
  }
}

static void threads(void) {
  uint32_t gp;
  __asm__ volatile("move %0, $gp" : "=r"(gp));
  uint32_t th = open_th(thread_main, thread_stack + sizeof thread_stack - 16, (void *)gp);
  CHECK_EQ("OpenTh handle", th, 0xFF000001);
  CHECK_EQ("TCB 1 in use", KWORD(KWORD(0x110) + 0xC0), 0x4000);
  CHECK_EQ("ChangeTh returns 1 on the way back", change_th(th), 1);
  change_th(th);
  CHECK_EQ("the thread ran twice", thread_ran, 2);
  CHECK_EQ("thread 0 current again", KWORD(KWORD(0x108)), KWORD(0x110));
  close_th(th);
  CHECK_EQ("CloseTh frees TCB 1", KWORD(KWORD(0x110) + 0xC0), 0x1000);
}

/* 7. FlushCache makes rewritten code visible to the i-cache. */
static uint32_t code[2];
static void flush_cache(void) {
  uint32_t (*f)(void) = (uint32_t(*)(void))code;
  code[0] = 0x03E00008; /* jr ra */
  code[1] = 0x24020001; /* li v0, 1 */
  bios_flush_cache();
  CHECK_EQ("first code", f(), 1);
  code[1] = 0x24020002; /* li v0, 2 */
  bios_flush_cache();
  CHECK_EQ("rewritten code after FlushCache", f(), 2);
}

int main(void) {
  table_of_tables();
  function_tables();
  blocks();
  psyqo_setup();
  break_event();
  threads();
  flush_cache();
  CHECK_EQ("Krom2RawAdd of a code with no glyph", krom2_raw_add(0), -1);
  return test_done("bios_kernel");
}
