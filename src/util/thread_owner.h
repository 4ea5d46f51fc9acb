// One object, one thread at a time (DESIGN.md: an environment is "owned by one thread at a
// time"): a call from a second thread while the first is inside a public entry of the same object
// fails at once with `std::runtime_error("<what> is in use by another thread")` instead of
// corrupting the object's state. A try-lock, not a mutex: waiting would hide the caller's bug and
// serialise threads the caller meant to run in parallel. The thread inside may re-enter (a Lua
// hook reading the environment, a run_until condition reading the console).
#pragma once
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

namespace psx {

class ThreadOwner {
 public:
  explicit ThreadOwner(const char* what) : what_(what) {}
  ThreadOwner(const ThreadOwner&) = delete;
  ThreadOwner& operator=(const ThreadOwner&) = delete;

  // Held for the length of one public call; the outermost Use of the owning thread releases it.
  class Use {
   public:
    explicit Use(ThreadOwner& o) : owner_(o) {
      const std::thread::id me = std::this_thread::get_id();
      std::thread::id free_id;
      if (o.owner_.compare_exchange_strong(free_id, me, std::memory_order_acquire)) {
        outermost_ = true;
      } else if (free_id != me) {
        throw std::runtime_error(std::string(o.what_) + " is in use by another thread");
      }
    }
    ~Use() {
      if (outermost_) owner_.owner_.store(std::thread::id(), std::memory_order_release);
    }
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;

   private:
    ThreadOwner& owner_;
    bool outermost_ = false;
  };

 private:
  std::atomic<std::thread::id> owner_{};
  const char* what_;
};

}  // namespace psx
