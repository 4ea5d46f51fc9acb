/* The pads are read at VBlank even when the VBlank root counter handler was set to acknowledge
   the IRQ and leave the exception (ChangeClearRCnt(3,1), psyqo's set-up; psx-spx "C(0Ah)"):
   StartPad turns that off, so the pad handler in chain 2 still runs after the root counter
   handler in chain 1, and StopPad turns it on again (OpenBIOS sio0/driver.c startPad/stopPad;
   Sony's pad library does the same after enqueueing its own handler). The VBlank event
   (F2000003h/0002h) keeps arriving meanwhile. Port 1 holds a digital pad: status 00h, ID 41h,
   no buttons pressed = FFFFh (psx-spx "Controllers - Communication Sequence"). */
#include "bios_calls.h"
#include "psx/test.h"

#define SPIN_LIMIT 20000000

static volatile uint32_t vblank_events;
static void vblank_callback(void) { ++vblank_events; }

static void wait_events(uint32_t target) {
  for (uint32_t i = 0; vblank_events < target && i < SPIN_LIMIT; ++i) {
  }
}

static uint8_t pad1[0x22], pad2[0x22];

int main(void) {
  uint32_t ev = open_event(0xF2000003, 2, 0x1000, vblank_callback);
  enable_event(ev);
  change_clear_rcnt(3, 1);
  start_rcnt(3);
  exit_critical_section();
  wait_events(3);
  CHECK_EQ("VBlank events before StartPad", vblank_events >= 3, 1);

  init_pad(pad1, 0x22, pad2, 0x22);
  enter_critical_section();
  start_pad();
  exit_critical_section();
  uint32_t before = vblank_events;
  wait_events(before + 3);
  CHECK_EQ("VBlank events after StartPad", vblank_events >= before + 3, 1);
  CHECK_EQ("pad 1 status", pad1[0], 0x00);
  CHECK_EQ("pad 1 ID", pad1[1], 0x41);
  CHECK_EQ("pad 1 buttons", pad1[2] | pad1[3] << 8, 0xFFFF);
  CHECK_EQ("pad 2 absent", pad2[0], 0xFF);
  CHECK_EQ("StartPad turned the VBlank auto-acknowledge off", change_clear_rcnt(3, 0), 0);

  enter_critical_section();
  stop_pad();
  exit_critical_section();
  CHECK_EQ("StopPad turned the VBlank auto-acknowledge on", change_clear_rcnt(3, 1), 1);
  enter_critical_section();
  I_MASK = 0;
  close_event(ev);
  exit_critical_section();
  return test_done("bios_pad_vblank");
}
