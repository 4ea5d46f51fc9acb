// Emulated time the HLE kernel books for the work a BIOS does in code: the kernel's handlers run
// natively here and would otherwise take no time, so programs would start their loops, see
// VBlanks and show their animation at other moments than under a BIOS. The figures are cycles of
// pcsx-redux's OpenBIOS (the open BIOS `psxrl compat --bios` compares with), measured in psxrl's
// interpreter from the exception (or the jump to the call vector) to the first instruction of
// the program's code, and from its last one to the return (docs/console.md, "HLE kernel's
// emulated time"): PSn00bSDK's timer and n00bdemo, psyqo's teapot; medians over 100-900 IRQs.
// Sony's BIOS takes other times; no figure here claims to be its. The interrupt figures pass at
// once (Scheduler::advance: a BIOS runs them with interrupts off); the calls' figures are spent
// in a kernel delay loop (HleBios::return_after) that interrupts may enter, as a BIOS's calls.
#pragma once
#include "core/types.h"

namespace psx::hle_cost {

// An interrupt's time follows the chains the kernel walks (psx-spx "Priority Chains"), measured
// per step of OpenBIOS's exception handler (kernel/vectors.s and handlers/irq.c, 100 frames each
// of PSn00bSDK's timer, n00bdemo and balls and psyqo's teapot; the figures are the steps' typical
// durations, which vary by some tens of cycles with the instruction cache):
// the exception up to the first chain: the registers into the TCB, Cause/EPC, the GTE test
// (398-534 cycles).
constexpr u32 kExceptionEntry = 470;
// Each priority chain visited (loop head and step, 13) and each element in it (load it, call its
// first function, test the result, step to the next: 22).
constexpr u32 kChainPriority = 13;
constexpr u32 kChainElement = 22;
// A kernel handler whose IRQ is not pending: the syscall handler and the root counter and pad
// handlers' I_MASK/I_STAT tests (20-98, typically 35-50 for the root counters).
constexpr u32 kHandlerMiss = 45;
// A root counter handler whose IRQ is pending: its tests and its second function (the event
// delivery is booked apart): 53-102 plus 41-65.
constexpr u32 kRcntHit = 135;
// DefInt (the IRQ handler of C0h:0Ch): eleven I_MASK/I_STAT tests, the events apart (430-560).
constexpr u32 kDefInt = 460;
// DeliverEvent walking the 16 EvCBs (SYSTEM.CNF's default count), a callback's own code apart
// (336-443).
constexpr u32 kDeliverEvent = 380;
// A SYSCALL (EnterCriticalSection, ExitCriticalSection...) from the instruction to the one after
// it: the exception handler's register save, the syscall handler, ReturnFromException (430-1242
// cycles in PSn00bSDK's timer and balls, median 582).
constexpr u32 kSyscall = 580;
// After the last chain: the longjmp through the exit buffer into the program's hook or into
// ReturnFromException (149-222).
constexpr u32 kChainExit = 180;
// ReturnFromException after an interrupt: registers back from the TCB, RFE, jump (384-407).
constexpr u32 kInterruptReturn = 400;
// The pad handler's poll at VBlank after StartPad: both ports over SIO, a digital pad in port 1
// and none in port 2 (psyqo teapot: 12,689 from the pad handler's first function to the next
// element).
constexpr u32 kPadPoll = 12700;
// One character through putchar/puts (B0h:3Dh: 5645 per call, 168 calls) and through printf
// (A0h:3Fh: 81105 cycles for 13 characters, 240771 for 37: about 6400 each, formatting included).
// A finer printf model (2570 a call, 6010 a character, 7775 a conversion, fitted on four lines of
// PSn00bSDK-2020 balls) missed ps1-tests spu-toolbox's longer lines (3900-7200 a character) and
// changed its picture; the flat figure keeps every compat picture.
constexpr u32 kTtyChar = 5645;
constexpr u32 kPrintfChar = 6400;

// InitPad (B0h:12h: 151,549 and 154,462 cycles, the second with a VBlank inside), StartPad
// (B0h:13h: 2207-2399) and FlushCache (A0h:44h: 8473). The other calls the examples make take
// 50-1600 cycles under OpenBIOS and none here.
constexpr u32 kInitPad = 151549;
constexpr u32 kStartPad = 2300;
constexpr u32 kFlushCache = 8473;
// _96_remove (A0h:56h/72h): OpenBIOS closes its five CD-ROM events and takes its CD-ROM handlers
// out of chain 0 (cdrom/cdrom.c, deinitCDRom): 4138 cycles in PSn00bSDK-2020 balls.
constexpr u32 kCdRemove = 4138;

// From power-on to the program's entry point: OpenBIOS hands an EXE over 491,100 cycles before
// the program's first VBlank starts (line 256 of 263, NTSC), 28 lines after the top of the
// frame, whatever the program; the HLE kernel, starting at line 0, would give the program 28
// lines more before its first VBlank. 28 lines of 3413 video cycles at 53.693175 MHz.
constexpr Cycles kBootCycles = Cycles{28} * 3413 * kCpuClockHz / 53693175;

}  // namespace psx::hle_cost
