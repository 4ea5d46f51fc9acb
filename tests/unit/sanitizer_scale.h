// How much of a randomized test runs: all of it in the release pass, a part of it in the
// sanitizer pass (scripts/test.sh), where ASan and UBSan run the emulator and the recompiler's
// code emission several times slower. Both passes run the same code paths; the release pass
// covers the rest of the seeds.
#pragma once

namespace test_scale {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// `full` in the release pass, `sanitized` in the sanitizer pass.
constexpr int sized(int full, int sanitized) { return kSanitized ? sanitized : full; }

}  // namespace test_scale
