// Idle-loop skipping: a program waiting for something (VBlank by polling I_STAT or GPUSTAT, a
// CD-ROM or DMA status bit, a RAM flag an interrupt handler sets, a countdown delay loop) spends
// most of its host time executing the same few instructions. Between two scheduled events nothing
// outside the CPU changes, so when one iteration of a loop provably leaves the machine as it found
// it (up to counters that advance by a fixed step), the iterations until the next event can be
// accounted for at once: time and the instruction count advance by whole iterations, the counters
// by their steps, and the interpreter resumes at the loop head before the event is due, exactly
// where it would have been. Skipping is therefore bit-identical to interpreting.
//
// How a loop qualifies, at its head (the target of a short backward branch):
//  1. One iteration is executed normally, instruction by instruction, and recorded. Before each
//     instruction it is vetted: multiply/divide, coprocessor, trapping and system instructions
//     disqualify the loop, as do stores other than whole words to RAM or the scratchpad (at most
//     four words, none of them code the loop runs or read in part), and loads from anything but
//     RAM, the scratchpad, the BIOS ROM or an I/O register whose read has no side effect and whose
//     value changes only at events or CPU writes (no timer counters, FIFOs, GPUREAD, SIO). No event
//     may fall due, no i-cache line may be filled (so every iteration costs the same cycles), no
//     hook may fire.
//  2. The recorded path is re-evaluated symbolically with every register and every stored word as
//     base + k*step (the step is what the recorded iteration added), proving that iteration k+1
//     starts from the registers and words of iteration k plus one step, and bounding k so that
//     every branch decision and load and store address along the path stays the same (other
//     loads return what they returned, as memory the loop does not store to and the allowed
//     registers cannot change before the next event). A C delay loop over a `volatile` counter
//     keeps its counter in such a word.
//  3. The largest whole number of iterations that ends before the next event and within that bound
//     is skipped; the stored words get the values the last of them would have stored.
// A loop usually reaches its head again right after the event that ended a skip (a pad
// transfer's loops wait out two SIO events a byte). Its next recorded iteration then mostly repeats
// one proven before, only started further along the same line (a spin counter a few iterations
// on), and that proof is reused instead of redone: step 2 is most of the cost of an examination.
// The last few proofs are kept, for loops that take turns. (Not for loops that store: a counter
// in memory shows in the loads' values, which then differ.)
// Most often not even the recording is needed (repeat()): where everything that shaped a proven
// iteration's path and time is as it was when it was recorded (the code and its i-cache lines,
// the pipeline and load shadow, SR, the cache and memory control registers) and every load
// would read what it read then, the iteration about to start follows the same path, so the
// proof, or one made again from here for the same path, covers it and those after it (always
// made again for a loop that stores, from the words' values now).
#pragma once
#include <array>

#include "core/cpu/idle_proof.h"
#include "core/cpu/register_line.h"
#include "core/scheduler.h"
#include "core/types.h"

namespace psx {

class Bus;
class Spu;
template <class BusT>
class CpuT;

class IdleSkip {
 public:
  static constexpr u32 kMaxPath = 64;  // instructions per iteration examined at most

  struct Stats {
    u64 skips = 0;       // times iterations were skipped
    u64 iterations = 0;  // loop iterations skipped in all
    u64 cycles = 0;      // CPU cycles they took
    u64 proofs = 0;      // proofs made (the other skips reused one)
    u64 examinations = 0;  // visits to a loop head that tried to skip (the rest back off)
    u64 repeats = 0;       // skips made from the head without recording an iteration (repeat())
    u64 unexamined = 0;    // visits where no proof covered the iteration and none was attempted
  };

  // Called by the CPU's run loop with pc at a loop head (and the loop head cleared); skips
  // iterations, or executes some, or does nothing.
  void at_loop_head(CpuT<Bus>& cpu);
  const Stats& stats() const { return stats_; }
  // The console's SPU, whose SPUSTAT changes between events unless told (Spu::
  // end_batches_at_flips): told when a loop reading SPUSTAT is first examined.
  void set_spu(Spu* spu) { spu_ = spu; }

  // What at_loop_head() reads and writes to let a backing-off loop head pass (below), for native
  // code that does the same without returning to its dispatcher (the recompiler's chain()): byte
  // offsets in an IdleSkip of last_head_ and of the backoff table, whose kBackoffEntries entries
  // of kBackoffBytes are {u32 head, visits, failures, leaving}, head at entry
  // (head >> 2) % kBackoffEntries.
  struct BackoffCells {
    int last_head, table;
  };
  // 4096 entries (64 KiB) cover 16 KiB of code without two heads sharing one. Heads that share
  // an entry take turns resetting it, so loops that can never qualify (a GTE call in their body,
  // say) are examined at nearly every visit: with 64 entries that was a third of Tumble's
  // examinations (2.6% of its host instructions); with 1024, heads 4 KiB apart in its 18 KiB of
  // code still made 43% of them (0.6%).
  static constexpr u32 kBackoffEntries = 4096, kBackoffBytes = 16, kBackoffVisits = 4;  // visits' offset
  static BackoffCells backoff_cells();

 private:
  // Records and proves one iteration from the loop head; skips when it can, as many iterations
  // as end before the next event (skipped_to_event) or as the proof covers (skipped_to_bound).
  // repeat() skips from the head (repeated), where the head is not met again at once.
  enum class Examined { refused, skipped_to_event, skipped_to_bound, repeated };
  Examined examine(CpuT<Bus>& cpu);
  static bool may_skip_here(const CpuT<Bus>& cpu);
  // The load delay slot: load_reg_, load_val_, new_load_reg_, new_load_val_.
  using Pipeline = std::array<u32, 4>;
  static Pipeline pipeline(const CpuT<Bus>& cpu);
  bool note_store(CpuT<Bus>& cpu, IdleStep& st);
  bool name_cells(Bus& bus);

  // A loop that could not be skipped (it stores other than to fixed words, reads a timer, exits,
  // or an event is due within its iteration) is examined again only after 2^failures - 1 more
  // visits to its head, so loops that never qualify cost little. An examination records an
  // iteration step by step (about 5,000 host instructions); with at most 4095 visits between two
  // (255 before) and the larger table, Tumble's examinations fell from 30 a move to 1.2, mostly
  // of its HUD's text loops. A wait loop that qualifies again after 12 refusals in a row is
  // interpreted for at most 4095 more iterations before it is skipped.
  static constexpr u32 kMaxBackoff = 12;
  // `leaving` counts the visits since an examination last succeeded here where a loop proven
  // here refused repeat() (at_loop_head()).
  struct Backoff {
    u32 head = 1;
    u32 visits = 0;
    u32 failures = 0;
    u32 leaving = 0;
  };
  std::array<Backoff, kBackoffEntries> backoff_{};
  // A proof made: the iteration recorded, the registers it started from and added, the load in
  // flight at its end, and its bound; and for repeat(), what else shaped the iteration (`at`:
  // the pipeline, SR, the cache and memory control registers, the load shadow when it started;
  // `checks`: its code, i-cache lines, jumps and loads), what it cost and what it left.
  struct Proven {
    u32 head = 1;
    u32 len = 0;
    std::array<IdleStep, kMaxPath> path{};
    std::array<u32, 32> before{};
    RegisterLine line;
    u32 load_reg = 0, load_val = 0;
    u64 max_k = 0;
    struct Context {
      Pipeline pipeline{};  // as pipeline() reads it
      u32 sr = 0, cache_control = 0;
      std::array<u32, 9> memory_control{};
      Cycles shadow = 0;  // cycles of the load shadow left
      u32 shadow_reg = 0;
    } at;
    // What repeats() checks, gathered once (note_context()): the distinct i-cache lines of the
    // steps with their tags (each the same all through the iteration, which filled no line); the
    // i-cache word each step is fetched from (a cached fetch hit, and hits again while its line's
    // tag is the same), or kFetchedElsewhere (not cached: memory); the targets of jumps (hooks);
    // the steps whose loads decide the path (not those of a stored word, whose value the proof
    // follows).
    struct Checks {
      static constexpr u16 kFetchedElsewhere = 0xFFFF;
      u32 lines = 0, jumps = 0, loads = 0;
      std::array<u32, kMaxPath> line{}, tag{}, jump_target{};
      std::array<u16, kMaxPath> fetched{};  // ICache::words() index
      std::array<u8, kMaxPath> load_step{};
    } checks;
    IdleCells cells;      // the words it stores to, before and after it (count 0: none)
    u32 named = 0;        // the registers its instructions name (bit r for register r)
    Cycles cost = 0;
    u64 steps = 0;
    u32 current_pc = 0;   // what it left: CpuT's current_pc_, in_delay_slot_, shadow_reg_,
    bool in_delay_slot = false;
    u32 shadow_reg = 0;
    bool load_done_moved = false;  // ... and load_done_at_ at `load_done` cycles from its start
    Cycles load_done = 0;
    // The proof repeats() last made again from the head, from what it depends on besides the
    // path, line and cells above: the registers, the load in flight and the stored words' values
    // (an IdleProof is a function of these). A loop that stores (a pad delay's `volatile`
    // counter) is met again from the same start at every call, and its proof is not redone.
    struct Reproof {
      bool valid = false;
      std::array<u32, 32> regs{};
      u32 load_reg = 0, load_val = 0;
      std::array<u32, IdleCells::kMax> words{};
      bool repeats = false;
      u64 max_k = 0;
    } reproof;
  };
  // Skips from the head when an iteration starting here is one that a proof covers (repeated).
  Examined repeat(CpuT<Bus>& cpu);
  bool repeats(CpuT<Bus>& cpu, Proven& p, u64& count);
  static bool same_start(const Proven::Reproof& r, const CpuT<Bus>& cpu, const IdleCells& cells, u32 named);
  void note_context(CpuT<Bus>& cpu, Proven& p, Cycles shadow0, u32 shadow_reg0, Cycles t0, Cycles done0,
                    u64 steps) const;
  // The bound for the iteration just recorded (path_, from `before` to `after`) taken from the
  // proofs made before, when one covers it; false when the proof must be made.
  bool reuse_proof(const std::array<u32, 32>& before, const std::array<u32, 32>& after, u32 load_reg,
                   u32 load_val, u64& max_k) const;
  // The proofs last made, replaced in turn: a pad transfer's loops polling for each byte and
  // for its acknowledgement take turns, each with two proofs (reuse_proof()). With 8, Tumble
  // made 80 proofs a move; with 16, 62 (most of them for its pad delays, loops that store);
  // with 32, 54.
  static constexpr size_t kProofs = 16;
  std::array<Proven, kProofs> proven_{};
  size_t proven_next_ = 0;
  // The loop last proven and what one iteration of it costs.
  u32 last_head_ = 1;
  Cycles last_cost_ = 0;
  std::array<IdleStep, kMaxPath> path_{};
  std::array<u32, kMaxPath> tags_{};  // i-cache tag of each step's line before its fetch
  IdleCells cells_;                   // the words the recorded iteration stores to
  u32 path_len_ = 0;
  Stats stats_;
  Spu* spu_ = nullptr;
};

}  // namespace psx
