/* Load and branch delay slots, checked from inside the console (routines in cpu_pipeline.S). */
#include "psx/test.h"

uint32_t load_delay_sees_old(const uint32_t *p);
uint32_t load_delay_arrives(const uint32_t *p);
uint32_t load_overwritten(const uint32_t *p);
uint32_t load_twice(const uint32_t *p);
uint32_t unaligned_pair(const uint8_t *p);
uint32_t mfc0_delay_sees_old(void);
uint32_t taken_branch_slot(void);
uint32_t untaken_branch_slot(void);
uint32_t jump_in_delay_slot(void);
uint32_t jal_link_offset(void);
uint32_t bltzal_untaken_link(void);

static uint32_t words[2] = {0xCAFEF00D, 0x12345678};
static uint8_t bytes[8] = {0x10, 0x21, 0x32, 0x43, 0x54, 0x65, 0x76, 0x87};

int main(void) {
  CHECK_EQ("load delay slot sees the old value", load_delay_sees_old(words), 0x1111);
  CHECK_EQ("load value arrives after the slot", load_delay_arrives(words), 0xCAFEF00D);
  CHECK_EQ("write in the delay slot beats the load", load_overwritten(words), 0x2222);
  CHECK_EQ("second of two loads wins", load_twice(words), 0x12345678);
  /* little-endian bytes 1..4: 0x54 0x43 0x32 0x21 */
  CHECK_EQ("LWR+LWL merge through the load delay", unaligned_pair(bytes), 0x54433221);
  CHECK_EQ("MFC0 has a load delay", mfc0_delay_sees_old(), 0x4444);
  CHECK_EQ("taken branch: slot runs, next skipped", taken_branch_slot(), 5);
  CHECK_EQ("untaken branch: slot and next run", untaken_branch_slot(), 0x55);
  CHECK_EQ("jump in a jump's delay slot", jump_in_delay_slot(), 0x101);
  CHECK_EQ("JAL links past its delay slot", jal_link_offset(), 0);
  CHECK_EQ("BLTZAL links when not taken", bltzal_untaken_link(), 8);
  return test_done("cpu_pipeline");
}
