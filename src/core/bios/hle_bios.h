// HLE kernel: runs PlayStation programs without a Sony BIOS. It puts the hardware in its post-boot
// state, lays out the kernel's RAM as a BIOS leaves it, owns the exception vector, and services
// the BIOS calls programs make through the A0h/B0h/C0h vectors and SYSCALL (psx-spx "Kernel
// (BIOS)"). Every call not listed here stops the console with a message naming it. Supported:
//   A0h:00h open  01h lseek  02h read  03h write  04h close  05h ioctl  06h exit  07h isatty
//       08h getc  09h putc  0Bh atof (faults: COP1)  0Ch strtol  0Dh strtoul  0Eh abs  0Fh labs
//       10h atoi  11h atol  13h setjmp  14h longjmp  15h strcat  16h strncat  17h strcmp
//       18h strncmp  19h strcpy  1Ah strncpy  1Bh strlen  1Ch index  1Dh rindex  1Eh strchr
//       1Fh strrchr  20h strpbrk  21h strspn  22h strcspn  23h strtok  24h strstr  25h toupper
//       26h tolower  27h bcopy  28h bzero  29h bcmp  2Ah memcpy  2Bh memset  2Ch memmove
//       2Dh memcmp  2Eh memchr  2Fh rand  30h srand  31h qsort  32h strtod (faults: COP1)
//       33h malloc  34h free  35h lsearch  36h bsearch  37h calloc  38h realloc  39h InitHeap
//       3Ah _exit  3Bh getchar  3Ch putchar  3Dh gets  3Eh puts  3Fh printf
//       41h LoadTest  42h Load  43h Exec  44h FlushCache
//       48h SendGP1Command  49h GPU_cw  4Ah GPU_cwp  4Dh GetGPUStatus  4Eh gpu_sync  51h LoadExec
//       54h/71h _96_init  55h/70h _bu_init  56h/72h _96_remove  78h CdAsyncSeekL
//       7Ch CdAsyncGetStatus  7Eh CdAsyncReadSector  81h CdAsyncSetMode  95h CdInitSubFunc
//       99h AddDummyTty  9Ch SetConf  9Dh GetConf  9Eh SetCdromIrqAutoAbort  9Fh SetMem  A0h _boot
//       A2h EnqueueCdIntr  A3h DequeueCdIntr  A4h CdGetLbn  A5h CdReadSector  A6h CdGetStatus
//       A7h-AAh, AEh bufs_cb_0-4  ABh _card_info  ACh _card_load  ADh _card_auto
//       AFh card_write_test  B4h GetSystemInfo; psx-spx's "returns 0" entries 57h-5Ah, 73h-77h,
//       79h-7Bh, 7Dh, 7Fh-80h, 82h-8Fh, B0h-B1h, B3h
//   B0h:00h alloc_kernel_memory  01h free_kernel_memory  02h SetRCnt  03h GetRCnt  04h StartRCnt
//       05h StopRCnt  06h ResetRCnt  07h DeliverEvent  08h OpenEvent  09h CloseEvent
//       0Ah WaitEvent  0Bh TestEvent  0Ch EnableEvent  0Dh DisableEvent  0Eh OpenTh  0Fh CloseTh
//       10h ChangeTh  12h InitPad  13h StartPad  14h StopPad  17h ReturnFromException
//       18h ResetEntryInt (SetDefaultExitFromException)  19h HookEntryInt (SetCustomExitFrom-
//       Exception)  20h UnDeliverEvent  32h-37h, 39h-3Ch as A0h:00h-05h, 07h-09h, 3Bh  38h exit
//       3Dh putchar  3Eh gets  3Fh puts  40h cd  41h format  42h firstfile2  43h nextfile
//       44h rename  45h erase  46h undelete  47h AddDevice  48h RemoveDevice (both accepted, no
//       effect)  49h PrintInstalledDevices  4Ah InitCARD2  4Bh StartCARD2  4Ch StopCARD2
//       4Dh _card_info_subfunc  4Eh _card_write  4Fh _card_read  50h _new_card
//       51h Krom2RawAdd (hle_font.h)  54h _get_errno  55h _get_error
//       56h GetC0Table  57h GetB0Table  58h _card_chan  5Bh ChangeClearPad  5Ch _card_status
//       5Dh _card_wait
//   C0h:00h EnqueueTimerAndVblankIrqs  01h EnqueueSyscallHandler  02h SysEnqIntRP
//       03h SysDeqIntRP  07h InstallExceptionHandlers  08h SysInitMemory  0Ah ChangeClearRCnt
//       0Ch InitDefInt  0Dh SetIrqAutoAck  1Ah set_card_find_mode  1Dh get_card_find_mode;
//       "returns 0" entries 0Eh-11h, 14h
//   SYSCALL a0=0 NoFunction, 1 EnterCriticalSection, 2 ExitCriticalSection, 3 ChangeThread-
//       SubFunction; other values deliver event F0000010h/4000h
// Files (hle_files.cpp): "tty:" (output to the host TTY, no input: getchar returns 0),
// "cdrom:" (hle_cdfs.cpp: the disc's ISO 9660 files, sectors read from the image at once) and
// "bu00:"/"bu10:" (hle_memcard.cpp: the emulated cards' directory and sectors, accessed at once,
// completion events delivered before the call returns). Executables (hle_exec.cpp) load from
// cdrom:. Not supported (they stop the console): the BIOS's internal device functions
// (A0h:5Bh-6Fh, 90h-98h) and kernel set-up calls not listed.
//
// Kernel RAM (psx-spx "BIOS Memory Map"), laid out at install(): the vectors at 80h (exception)
// and A0h/B0h/C0h, the table of tables at 100h (ExCB, PCB, TCB, EvCB pointers and sizes), the
// A/C/B function tables at 200h/674h/874h. The vectors hold a marker the hook recognises; a call
// through a vector looks its function up in the RAM table, so a program that patches a table
// entry gets its own function called. Each table entry initially points at a small stub
// ("j tail; li t1,fn", the tail jumps to the vector's KSEG1 mirror), and a call reaching a
// vector through KSEG1 is run natively without the table lookup, so programs that keep the old
// entry and chain to it work. The exception chains, events and threads live in the ExCB, EvCB
// and TCB blocks in RAM, so programs that clear or walk them (psyqo does) see what they expect.
//
// Interrupts are handled as the BIOS does (psx-spx "BIOS Interrupt/Exception Handling"): the
// registers go to the current thread's TCB, then the four priority chains are walked
// (elements {next, func2, func1, pad}; func2(v0) runs when func1 returns non-zero), then the
// exit buffer set by HookEntryInt is longjmp'd to (by default it calls ReturnFromException).
// The kernel's own chain elements run natively: the root counter handlers (C0h:00h, chain 1:
// VBlank for root counter 3, timers 2, 1, 0: deliver F200000xh/0002h, and when ChangeClearRCnt
// is on acknowledge and return), the pad handler (chain 2, after StartPad: reads both pads into
// the InitPad buffers at VBlank) and DefInt (C0h:0Ch, chain 3: delivers F000000xh/1000h for each
// pending IRQ and acknowledges those SetIrqAutoAck turned on). Other exceptions (break, address
// errors...) reach the syscall handler's element, which delivers F0000010h/1000h and calls
// A0h:40h through the A table: a program's replacement resolves the exception; with the
// kernel's own entry the console stops with a message. A load in flight when the CPU reaches a
// vector lands before the kernel runs (land_pending_load). Program functions are called with ra pointing at a kernel stub that
// executes SYSCALL, which hands control back. A program that returns from its entry point stops
// the console. With a real BIOS the console keeps only the putchar hooks and the shell hook.
#pragma once
#include <array>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/bios/exe.h"
#include "core/bios/hle_io.h"
#include "core/cpu/cpu.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Bus;
class MemoryCard;
class SioDevice;
namespace disc {
class Disc;
}

class HleBios {
 public:
  // Puts the kanji font into the ROM image (hle_font.h), which a BIOS image loaded later replaces.
  HleBios(Cpu& cpu, Bus& bus, Scheduler& sched);

  // Writes the kernel's vectors, tables and stubs into RAM and sets SR/I_MASK as the BIOS leaves
  // them.
  void install();
  // Where a program's entry point returns to (the BIOS's Exec() caller): stops the console.
  static constexpr u32 kExitStub = 0x80000520;
  // Handles the CPU reaching a hooked vector. Returns false when the vector holds program code
  // (the program replaced the kernel's handler), so the CPU should just run it.
  bool handle(u32 pc);
  // Starts the loaded program at `entry` once the kernel's boot time (hle_costs.h) has run.
  void start_program(u32 entry);

  std::function<void(char)> on_tty;
  std::function<void(const std::string&)> on_log;
  std::function<void(const std::string&)> on_fatal;
  // The program called exit/_exit with this code (hle_stdlib.cpp).
  std::function<void(u32)> on_exit;
  // The controller in port 0/1 for the kernel's pad handler (nullptr when none is plugged).
  std::function<SioDevice*(int port)> pad_at;
  // The disc in the drive and the memory card in slot 0/1 for the file functions (nullptr: none).
  std::function<disc::Disc*()> disc_in_drive;
  std::function<MemoryCard*(int slot)> card_at;

  void do_state(StateIO& s);

  // Marker instruction the kernel places at each vector it owns: LUI $zero, 0x484C ("HL").
  static constexpr u32 kMarker = 0x3C00484C;

 private:
  // Kernel RAM layout (the first 64 KiB belong to the kernel, psx-spx "BIOS Memory Map").
  static constexpr u32 kTables = 0x80000100;       // pointers and sizes of ExCB, PCB, TCB, EvCB
  static constexpr u32 kTableA = 0x80000200, kTableC = 0x80000674, kTableB = 0x80000874;
  static constexpr u32 kSizeA = 0xC0, kSizeB = 0x80, kSizeC = 0x20;  // entries
  static constexpr u32 kReturnStub = 0x80000500;   // SYSCALL: a called program function returned
  static constexpr u32 kRetryA0 = 0x80000508;      // re-enters A0h with the same t1 (busy waits)
  static constexpr u32 kRetryB0 = 0x80000510;
  static constexpr u32 kRfeStub = 0x80000518;      // calls B0h:17h ReturnFromException
  // "loop: addiu t0,t0,-1; bgtz t0,loop; nop; jr ra; nop": a call that takes a BIOS's time
  // (return_after) returns through it, interruptible as the BIOS's code is.
  static constexpr u32 kDelayStub = 0x80000528;
  static constexpr u32 kNativeFuncs = 0x80000540;  // pseudo addresses of the native handlers
  static constexpr u32 kKernelElems = 0x80000580;  // the kernel's chain elements, 16 bytes each
  static constexpr u32 kDefaultExit = 0x80000600;  // ResetEntryInt's jmp_buf
  // "loop: bgtz t0,loop; addiu t0,t0,-1; jr k0; move t0,zero": the kernel's boot time before the
  // program's entry (start_program).
  static constexpr u32 kBootStub = 0x80000630;
  static constexpr u32 kVersionString = 0x80000640;
  static constexpr u32 kFpuStub = 0x80000660;  // atof/strtod: a COP1 instruction (hle_stdlib.cpp)
  static constexpr u32 kRamSizeWord = 0x80000060;
  static constexpr u32 kStubs = 0x80001000;        // one "j tail; li t1,fn" per table entry
  static constexpr u32 kStubTails = 0x80001B00;    // per table: jump to the KSEG1 vector
  static constexpr u32 kExecReturn = 0x80001B40;   // where a program started by Exec returns to
  static constexpr u32 kKernelHeap = 0x8000A000, kKernelHeapEnd = 0x8000E000;
  static constexpr u32 kExceptionStack = 0x8000EFF0;
  static constexpr u32 kMaxEvents = 16;  // SYSTEM.CNF default "EVENT = 10" (hex)
  static constexpr u32 kMaxThreads = 4;  // SYSTEM.CNF default "TCB = 4"
  static constexpr u32 kEvcbSize = 0x1C, kTcbSize = 0xC0;
  enum Native : u32 { kRcntVblank, kRcnt2, kRcnt1, kRcnt0, kPad, kDefInt, kSyscallHandler, kNativeCount };

  // What to do when a program function called by the kernel returns.
  struct Resume {
    enum Kind : u32 { kChainFunc1, kDispatch, kCaller, kSearch } kind;
    u32 value;  // kChainFunc1: its func2; kCaller: the caller's ra
    u32 in_dispatch;
  };
  struct Heap {
    u32 start = 0, end = 0;
  };
  // qsort/lsearch/bsearch in progress (hle_stdlib.cpp): arguments, the caller's ra, and the step.
  struct Search {
    enum Op : u32 { kNone, kQsort, kLsearch, kBsearch } op = kNone;
    u32 key = 0, base = 0, nel = 0, width = 0, cmp = 0, ra = 0;
    u32 i = 0, lo = 0, hi = 0, mid = 0;  // lsearch: element i; bsearch/qsort: [lo, hi), mid
    u32 temp = 0;                        // qsort: the heap block an element moves through
  };

  // Dispatch (hle_bios.cpp).
  void call_a0(u32 fn);
  void call_b0(u32 fn);
  void call_c0(u32 fn);
  void land_pending_load();
  void return_to_caller(u32 v0);
  void return_after(u32 v0, Cycles cycles);
  void unsupported(const char* table, u32 fn);
  bool tty_call(u32 table, u32 fn);
  bool system_call(u32 table, u32 fn);
  bool kernel_setup_call(u32 fn, u32 a0, u32 a1);
  void set_mem(u32 megabytes);

  void load_v2_state(StateIO& s);

  // Kernel tables, table dispatch and threads (hle_kernel_tables.cpp).
  void install_tables();
  bool via_table(u32 vector, u32 pc);
  u32 chain_head(u32 prio) const;
  void set_chain_head(u32 prio, u32 elem);
  u32 current_tcb() const;
  bool table_call(u32 table, u32 fn);
  bool thread_call(u32 fn);

  // Exceptions and interrupts (hle_interrupts.cpp).
  void exception();
  void syscall();
  void kernel_stub_syscall();
  void fail_exception();
  void save_thread_registers();
  void return_from_exception();
  void dispatch_next();
  bool run_native(u32 id);
  bool unresolved_exception();
  bool rcnt_handler(u32 counter);
  bool pad_handler();
  bool def_int();
  void read_pad(int port, u32 buf);
  void call_guest(u32 func, u32 a0, Resume r);
  void guest_returned();
  void enqueue(u32 prio, u32 elem);
  void dequeue(u32 prio, u32 elem);
  bool interrupt_call(u32 table, u32 fn);
  bool timer_call(u32 fn);

  // Events (hle_events.cpp): control blocks in the EvCB array (psx-spx "BIOS Event Functions").
  bool event_call(u32 fn);
  void deliver_event(u32 cls, u32 spec);
  u32 event_at(u32 handle) const;

  // Memory allocation (hle_memory.cpp).
  bool memory_call(u32 table, u32 fn);
  u32 heap_alloc(Heap& h, u32 size);
  void heap_free(Heap& h, u32 ptr);
  u32 heap_realloc(Heap& h, u32 ptr, u32 size);

  // String, memory and number functions of table A0h (hle_string.cpp).
  bool string_call(u32 fn);
  bool memory_fill_call(u32 fn);
  u32 str_to_long(u32 src, u32 end_ptr, u32 base);
  s32 compare(u32 a, u32 b, u32 n, bool stop_at_nul) const;

  // Searching, sorting, floating point and exit (hle_stdlib.cpp).
  bool stdlib_call(u32 table, u32 fn);
  void program_exit(const char* name, u32 code);
  void start_search(Search::Op op, u32 key, u32 base, u32 nel, u32 width, u32 cmp);
  void next_comparison();
  void compare(u32 a, u32 b);
  void comparison_returned(s32 result);
  void insert_element(u32 from, u32 to);
  void finish_search(u32 v0);

  // printf formatting (hle_printf.cpp).
  std::string format(u32 fmt_addr) const;

  // File functions (hle_files.cpp): handles, the TTY, firstfile/nextfile; the cdrom: device
  // (hle_cdfs.cpp) and the memory cards (hle_memcard.cpp). State in io_ (hle_io.h).
  struct DirEntry {
    std::string name;
    u32 attr, size, sector;
  };
  bool io_call(u32 table, u32 fn);
  bool file_call(u32 fn);
  bool file_call_b0(u32 fn);
  u32 file_open(u32 path, u32 mode);
  u32 file_read(u32 fd, u32 dst, u32 len);
  u32 file_write(u32 fd, u32 src, u32 len);
  u32 file_lseek(u32 fd, u32 offset, u32 whence);
  u32 file_close(u32 fd);
  u32 file_fail(HleFile* f, u32 err);
  HleFile* file_at(u32 fd);
  u32 first_file(u32 path, u32 entry);
  u32 next_file(u32 entry);
  std::vector<DirEntry> device_entries();
  void return_after_events(u32 v0);
  bool cd_call(u32 fn);
  u32 cd_open(const std::string& path, HleFile& f);
  u32 cd_read(HleFile& f, u32 dst, u32 len);
  bool cd_read_blocks(u32 lba, u32 count, u32 dst);
  std::string cd_full_path(const std::string& path) const;
  std::vector<DirEntry> cd_entries(const std::string& dir);
  u32 file_rename(u32 from_addr, u32 to_addr);
  u32 file_undelete(u32 path_addr);
  bool cd_async_call(u32 fn);
  bool cd_sectors(u32 lba, u32 count, u32 size, std::vector<u8>& out);
  bool cd_to_ram(u32 lba, u32 count, u32 size, u32 dst);
  bool card_call(u32 table, u32 fn);
  bool card_call_a0(u32 fn);
  bool card_call_b0(u32 fn);
  u32 card_rename(u32 port, const std::string& from, const std::string& to);
  u32 card_undelete(u32 port, const std::string& name);
  u32 card_format(u32 port);
  u32 card_open(u32 port, const std::string& name, u32 mode, HleFile& f);
  u32 card_transfer(HleFile& f, u32 addr, u32 len, bool write);
  bool card_erase(u32 port, const std::string& name);
  std::vector<DirEntry> card_entries(u32 port);
  bool card_sector(u32 port, u32 sector, u32 addr, bool write);
  void card_deliver(u32 port, bool info);

  // Executables (hle_exec.cpp).
  bool exec_call(u32 fn);
  bool exe_load(u32 path_addr, u32 headerbuf, bool body);
  bool read_exe(const std::string& path, PsxExe& exe, std::vector<u8>& header, std::string& error);
  void copy_text(const PsxExe& exe);
  void zero_fill(u32 addr, u32 size);
  void exec(u32 headerbuf, u32 param1, u32 param2);
  void load_exec(const std::string& path, u32 stack_base, u32 stack_offset);
  void warm_boot();
  void start(const PsxExe& exe, u32 sp, u32 param1, u32 param2);
  bool null_call(u32 table, u32 fn);

  u8 peek8(u32 addr) const;
  u32 peek32(u32 addr) const;
  void poke8(u32 addr, u8 v);
  void poke32(u32 addr, u32 v);
  u32 io_read(u32 addr, u32 width);
  void io_write(u32 addr, u32 v, u32 width);
  std::string read_string(u32 addr) const;
  u32 arg(u32 i) const;
  void print(const std::string& s);

  Cpu& cpu_;
  Bus& bus_;
  Scheduler& sched_;  // books the emulated time of the kernel's work (hle_costs.h)
  u32 exit_buf_ = kDefaultExit;
  bool dispatching_ = false;
  bool return_now_ = false;
  bool unresolved_ = false;  // dispatching an exception no handler may resolve
  u32 chain_prio_ = 0, chain_elem_ = 0;
  std::vector<Resume> resume_;
  std::vector<u32> callbacks_;
  std::array<u32, 4> clear_rcnt_{1, 1, 1, 1};
  u32 irq_auto_ack_ = 0;  // SetIrqAutoAck: bit n set = DefInt acknowledges IRQ n
  u32 clear_pad_ = 1;
  std::array<u32, 2> pad_buf_{};
  bool pad_started_ = false;
  Heap heap_, kernel_heap_;
  u32 rand_seed_ = 0x24040001;
  u32 strtok_next_ = 0;
  std::array<u32, 3> conf_{};  // SetConf: EvCB count, TCB count, stack top
  std::set<u32> warned_;
  HleIoState io_;
  HleIoState2 io2_;
  Search search_;
};

}  // namespace psx
