// Fuzzes PS-X EXE files (src/core/bios/exe.h): the header parser, then, for a file it accepts,
// the HLE boot that loads the text, clears the BSS and starts the program, run for a bounded
// number of cycles. Defects must be InputErrors; whatever the accepted program does is guest
// behaviour and must not crash the host.
#include <vector>

#include "core/console.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const std::vector<psx::u8> file(data, data + size);
  try {
    psx::PsxExe::parse(file, "fuzz.exe");
  } catch (const psx::InputError&) {
    return 0;
  }
  psx::Console console;
  console.boot_exe_image(file, "fuzz.exe");
  console.run_cycles(20000);
  return 0;
}
