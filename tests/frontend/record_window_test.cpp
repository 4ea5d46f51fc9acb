// psxrl record in the window, as a person records a session: xdotool (under xvfb-run) presses
// F3 on Tumble's title (mark 3, labelled level_start by default), Enter (Start), F1 (mark 1,
// "score") and Escape. Expectations from Tumble's rules (games/tumble/README.md: state 50 title,
// 56 level select, which Start opens) and the key map of docs/play.md (Enter = Start, F1..F4
// marks); the session must replay exactly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/console.h"
#include "core/sio/pad.h"
#include "memsearch/recorder.h"
#include "memsearch/session.h"
#include "test_support.h"

namespace fs = std::filesystem;

TEST(PlayWindow, RecordSetsMarksFromFunctionKeysAndReplays) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  const fs::path dir = fs::path(PSXRL_TEST_OUT_DIR) / "record_window";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path session = dir / "session";
  std::ofstream script(dir / "keys.sh");
  script << "SDL_AUDIODRIVER=dummy " << PSXRL_BUILD_DIR << "/psxrl record --exe " << PSXRL_BUILD_DIR
         << "/games/tumble/tumble.exe --interval 30 --out " << session << " > " << (dir / "record.out") << " 2>&1 &\n"
         << "pid=$!\n"
         << "timeout 30 " << PSXRL_XDOTOOL << " search --sync --name 'psxrl: ' windowfocus --sync || { kill $pid; exit 99; }\n"
         // The title is up within a second of the window (state 50 by frame 31 in the demo).
         << "sleep 1\n" << PSXRL_XDOTOOL << " key F3\nsleep 0.3\n"
         << PSXRL_XDOTOOL << " keydown Return\nsleep 0.25\n" << PSXRL_XDOTOOL << " keyup Return\nsleep 0.8\n"
         << PSXRL_XDOTOOL << " key F1\nsleep 0.3\n" << PSXRL_XDOTOOL << " key Escape\n"
         << "wait $pid\ncode=$?\ncat " << (dir / "record.out") << "\nexit $code\n";
  script.close();
  auto r = psxrl::test::run("sh " + (dir / "keys.sh").string());
  ASSERT_EQ(r.code, 0) << r.output;

  psxrl::memsearch::Session s = psxrl::memsearch::read_session(session.string());
  ASSERT_EQ(s.marks.size(), 2u) << r.output;
  EXPECT_EQ(s.marks[0].label, "level_start");
  EXPECT_EQ(s.marks[1].label, "score");
  ASSERT_LT(s.marks[0].frame, s.marks[1].frame);
  bool start_held = false;
  for (psx::u64 f = s.marks[0].frame; f <= s.marks[1].frame; ++f) start_held |= (s.pad1[f] & psx::pad_button::kStart) != 0;
  EXPECT_TRUE(start_held) << "Enter was held between the marks";
  auto state = [&](const psxrl::memsearch::Mark& m) {
    const auto& snap = s.snapshots[static_cast<size_t>(s.snapshot_at(m.frame))];
    return snap[0x10008] | snap[0x10009] << 8;  // the contract's state word, low half
  };
  EXPECT_EQ(state(s.marks[0]), 50) << "the title";
  EXPECT_EQ(state(s.marks[1]), 56) << "Start opened level select";

  psx::Console console;
  psxrl::memsearch::boot_source(console, s.source);
  EXPECT_FALSE(psxrl::memsearch::replay_session(console, s).has_value());
}
