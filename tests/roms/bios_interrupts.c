/* The HLE kernel's interrupt handling and events, used as SDK code uses them (psx-spx "BIOS
   Interrupt/Exception Handling", "BIOS Event Functions", "BIOS Timer Functions", "BIOS Joypad
   Functions"): a priority-chain element counting VBlanks (func2 gets func1's return value), a
   HookEntryInt handler (PSn00bSDK's way), root counter 2 delivering events to a ready-mode and a
   callback-mode event, events delivered by the program, and the pad buffers of InitPad. */
#include "bios_calls.h"
#include "psx/test.h"

#define SPIN_LIMIT 20000000

static volatile uint32_t vblanks, func2_sum, hook_calls, timer_callbacks, user_callbacks;

/* Chain element func1: claims and acknowledges VBlank; its non-zero result goes to func2. */
static int vblank_func1(void) {
  if (!(I_STAT & I_MASK & 1)) return 0;
  I_STAT = ~1u;
  ++vblanks;
  return 3;
}
static void vblank_func2(int v) { func2_sum += v; }
static uint32_t element[4];

static uint8_t isr_stack[1024];
static uint32_t hook_buf[12];
static void hook_isr(void) {
  if (I_STAT & 1) {
    I_STAT = ~1u;
    ++hook_calls;
  }
  return_from_exception();
}

static void timer_callback(void) { ++timer_callbacks; }
static void user_callback(void) { ++user_callbacks; }

static void wait_for(volatile uint32_t *counter, uint32_t target) {
  for (uint32_t i = 0; *counter < target && i < SPIN_LIMIT; ++i) {
  }
}

static uint8_t pad1[0x22], pad2[0x22];

int main(void) {
  /* 1. A priority-0 chain element sees every VBlank; removed, it sees none. */
  element[1] = (uint32_t)vblank_func2;
  element[2] = (uint32_t)vblank_func1;
  enter_critical_section();
  sys_enq_int_rp(0, element);
  I_STAT = 0;
  I_MASK = 1;
  exit_critical_section();
  wait_for(&vblanks, 5);
  CHECK_EQ("chain element counted 5 VBlanks", vblanks >= 5, 1);
  CHECK_EQ("func2 got func1's result each time", func2_sum, vblanks * 3);
  enter_critical_section();
  sys_deq_int_rp(0, element);
  exit_critical_section();
  uint32_t before = vblanks;
  hook_buf[0] = (uint32_t)hook_isr;
  hook_buf[1] = (uint32_t)(isr_stack + sizeof isr_stack - 16);
  __asm__ volatile("sw $gp, %0" : "=m"(hook_buf[11]));

  /* 2. HookEntryInt: after the chains the kernel longjmps into the hook, which acknowledges
        and calls ReturnFromException; the removed element no longer counts. Root counter 3's
        handler (chain 1) takes VBlank and leaves the exception at once while its auto-
        acknowledge is on, so the SDKs turn it off first (PSn00bSDK's ResetGraph does). */
  CHECK_EQ("ChangeClearRCnt(3) was on at boot", change_clear_rcnt(3, 0), 1);
  enter_critical_section();
  hook_entry_int(hook_buf);
  exit_critical_section();
  wait_for(&hook_calls, 4);
  CHECK_EQ("hook saw 4 VBlanks", hook_calls >= 4, 1);
  CHECK_EQ("dequeued element idle", vblanks, before);
  enter_critical_section();
  I_MASK = 0;
  CHECK_EQ("ResetEntryInt returns its buffer", reset_entry_int() != 0, 1);
  exit_critical_section();

  /* 3. Root counter 2 (target 1000h, IRQ at target, system clock / 8) delivers F2000002h/2:
        the ready-mode event wakes WaitEvent, the callback-mode event runs its function. */
  CHECK_EQ("ChangeClearRCnt returns the old flag (on at boot)", change_clear_rcnt(2, 1), 1);
  enter_critical_section();
  uint32_t ev = open_event(0xF2000002, 2, 0x2000, 0);
  uint32_t cb = open_event(0xF2000002, 2, 0x1000, timer_callback);
  CHECK_EQ("event handle class", ev >> 24, 0xF1);
  CHECK_EQ("two handles differ", ev != cb, 1);
  enable_event(ev);
  enable_event(cb);
  CHECK_EQ("SetRCnt", set_rcnt(2, 0x1000, 0x1000), 1);
  start_rcnt(2);
  CHECK_EQ("StartRCnt sets I_MASK bit 6", I_MASK & 0x40, 0x40);
  exit_critical_section();
  CHECK_EQ("WaitEvent on the timer event", wait_event(ev), 1);
  CHECK_EQ("the callback ran with it", timer_callbacks >= 1, 1);
  CHECK_EQ("TestEvent right after: consumed", test_event(ev), 0);
  wait_for(&timer_callbacks, 4);
  CHECK_EQ("callback keeps running", timer_callbacks >= 4, 1);
  CHECK_EQ("callback events never become ready", test_event(cb), 0);
  stop_rcnt(2);
  CHECK_EQ("StopRCnt clears I_MASK bit 6", I_MASK & 0x40, 0);
  disable_event(ev);
  CHECK_EQ("WaitEvent on a disabled event returns 0", wait_event(ev), 0);
  close_event(ev);
  close_event(cb);

  /* 4. Events delivered by the program. */
  uint32_t u = open_event(0xF3000001, 4, 0x2000, 0);
  CHECK_EQ("disabled event not ready", test_event(u), 0);
  deliver_event(0xF3000001, 4);
  CHECK_EQ("delivery to a disabled event is lost", (enable_event(u), test_event(u)), 0);
  deliver_event(0xF3000001, 8);
  CHECK_EQ("other spec does not match", test_event(u), 0);
  deliver_event(0xF3000001, 4);
  CHECK_EQ("delivered: ready", test_event(u), 1);
  CHECK_EQ("TestEvent consumed it", test_event(u), 0);
  deliver_event(0xF3000001, 4);
  undeliver_event(0xF3000001, 4);
  CHECK_EQ("UnDeliverEvent makes it busy again", test_event(u), 0);
  close_event(u);
  uint32_t c = open_event(0xF3000002, 4, 0x1000, user_callback);
  enable_event(c);
  deliver_event(0xF3000002, 4);
  CHECK_EQ("callback ran before DeliverEvent returned", user_callbacks, 1);
  close_event(c);
  deliver_event(0xF3000002, 4);
  CHECK_EQ("closed event gets nothing", user_callbacks, 1);

  /* 5. InitPad zero-fills the buffers; after StartPad, VBlank reads port 1's digital pad
        (status 00h, ID 41h, no buttons = FFFFh active-low) and reports port 2 empty (FFh). */
  bios_memset(pad1, 0x77, sizeof pad1);
  bios_memset(pad2, 0x77, sizeof pad2);
  init_pad(pad1, 0x22, pad2, 0x22);
  CHECK_EQ("InitPad zero-fills", pad1[0] == 0 && pad1[0x21] == 0 && pad2[5] == 0, 1);
  enter_critical_section();
  start_pad();
  exit_critical_section();
  for (uint32_t i = 0; pad1[1] != 0x41 && i < SPIN_LIMIT; ++i) {
    __asm__ volatile("" ::: "memory");
  }
  CHECK_EQ("pad 1 status", pad1[0], 0x00);
  CHECK_EQ("pad 1 ID", pad1[1], 0x41);
  CHECK_EQ("pad 1 buttons", pad1[2] | pad1[3] << 8, 0xFFFF);
  CHECK_EQ("pad 2 absent", pad2[0], 0xFF);
  enter_critical_section();
  stop_pad();
  I_MASK = 0;
  exit_critical_section();
  return test_done("bios_interrupts");
}
