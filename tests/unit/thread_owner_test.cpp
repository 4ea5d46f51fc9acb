// One environment, console or vector environment used from two threads at once (#61): the
// second thread's call fails with "<what> is in use by another thread" and the object stays
// usable. The first thread is held inside its call by a callback the object runs (a frame
// callback, a run_until condition) until the second has tried, so every case is deterministic.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/console.h"
#include "util/thread_owner.h"
#include "rl/async_vec_env.h"
#include "rl/env.h"
#include "rl/vec_env.h"

namespace {

using psxrl::rl::Env;
using psxrl::rl::EnvConfig;

const std::string kTumbleExe = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";

// Runs `inside` on another thread; when that thread reaches the gate (a callback calls wait()),
// runs `second` here and lets the other thread go on. Returns the message `second` threw.
class Gate {
 public:
  void wait() {
    if (held_.exchange(true)) return;  // only the first arrival is held
    reached_.set_value();
    release_.get_future().wait();
  }
  template <typename Inside, typename Second>
  std::string collide(Inside inside, Second second) {
    std::thread t(inside);
    reached_.get_future().wait();
    std::string error;
    try {
      second();
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
    release_.set_value();
    t.join();
    return error;
  }

 private:
  std::atomic<bool> held_{false};
  std::promise<void> reached_, release_;
};

TEST(ThreadOwner, ASecondThreadIsRefusedAndTheOwnerMayReenter) {
  psx::ThreadOwner owner("Thing");
  Gate gate;
  std::string error = gate.collide(
      [&] {
        psx::ThreadOwner::Use use(owner);
        psx::ThreadOwner::Use again(owner);  // the owner's own nested call
        gate.wait();
      },
      [&] { psx::ThreadOwner::Use use(owner); });
  EXPECT_EQ(error, "Thing is in use by another thread");
  psx::ThreadOwner::Use after(owner);  // released by the outermost Use
}

TEST(ThreadOwner, ConsoleRefusesASecondThreadAndRunsOnAfterwards) {
  psx::Console console;
  console.boot_exe(kTumbleExe);
  Gate gate;
  std::string error = gate.collide([&] { console.run_until([&] { return gate.wait(), true; }, 10); },
                                   [&] { console.run_frame(); });
  EXPECT_EQ(error, "Console is in use by another thread");
  const auto frames = console.frames();
  console.run_frames(2);
  EXPECT_EQ(console.frames(), frames + 2);
}

TEST(ThreadOwner, EnvRefusesASecondThreadAndStepsOnAfterwards) {
  Env env(EnvConfig{});
  env.reset(1, 1);
  Gate gate;
  env.on_frame = [&](auto) { gate.wait(); };
  std::string error = gate.collide([&] { env.step(0); }, [&] { env.step(1); });
  EXPECT_EQ(error, "Env is in use by another thread");
  env.on_frame = nullptr;
  env.reset(1, 1);
  EXPECT_EQ(env.step(0).info.moves, 1u);
}

TEST(ThreadOwner, VecEnvRefusesASecondThread) {
  psxrl::rl::VecEnv vec(EnvConfig{}, 2, 2);
  vec.reset(1, 1);
  Gate gate;
  vec.env(0).on_frame = [&](auto) { gate.wait(); };
  std::string error = gate.collide([&] { vec.step({0, 0}); }, [&] { vec.reset(1, 2); });
  EXPECT_EQ(error, "VecEnv is in use by another thread");
  vec.env(0).on_frame = nullptr;
  EXPECT_EQ(vec.step({0, 0}).infos[1].moves, 2u);
}

// AsyncVecEnv: the first thread waits inside recv() for environment 0, whose move is held at its
// first frame; the second thread tries a call that changes nothing (sending no moves) until it is
// refused, which it must be once the first thread is inside recv().
TEST(ThreadOwner, AsyncVecEnvRefusesASecondThread) {
  psxrl::rl::AsyncVecEnv vec(EnvConfig{}, 1, 1, 1);
  vec.reset(1, 1);
  vec.recv();
  Gate gate;
  vec.env(0).on_frame = [&](auto) { gate.wait(); };
  vec.send({0}, {0});
  std::string error = gate.collide([&] { vec.recv(); }, [&] {
    for (int tries = 0; tries < 10000; ++tries) {
      vec.send({}, {});
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  EXPECT_EQ(error, "AsyncVecEnv is in use by another thread");
  vec.env(0).on_frame = nullptr;
  vec.send({1}, {0});
  EXPECT_EQ(vec.recv().infos[0].moves, 2u);
}

}  // namespace
