// Fuzzes `psxrl run --input` scripts (src/cli/input_script.h): any text either parses into
// presses or is refused with psx::InputError naming the line.
#include <string>

#include "cli/input_script.h"
#include "core/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    auto presses = psxrl::cli::parse_input_script(text, "fuzz.txt");
    // The documented contract: frames never go backwards.
    for (size_t i = 1; i < presses.size(); ++i)
      if (presses[i].frame < presses[i - 1].frame) __builtin_trap();
  } catch (const psx::InputError&) {
  }
  return 0;
}
