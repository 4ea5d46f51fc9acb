// Guest-side fuzzing of the CPU (and, through its loads and stores, the bus and every device
// register): the input is a stream of instruction words booted as a PS-X EXE at 0x80010000 on the
// HLE kernel and run for a bounded number of cycles. Bad opcodes, wild jumps and odd device
// accesses are guest behaviour: they may stop the console, never crash the host.
#include <vector>

#include "core/console.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  if (size > 64 * 1024) return 0;  // a longer stream adds nothing the bounded run can reach
  psx::Console console;
  console.boot_exe_image(psxfuzz::make_exe(std::vector<psx::u8>(data, data + size)), "fuzz.exe");
  console.run_cycles(50000);
  return 0;
}
