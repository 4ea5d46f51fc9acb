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

// Exception entry up to the first interrupt handler of the program: the register save into the
// TCB and the walk over the kernel's chain elements (1966-2014 cycles for the timer and VBlank
// IRQs of a PSn00bSDK program whose handler is reached through HookEntryInt).
constexpr u32 kInterruptEntry = 1970;
// ReturnFromException after an interrupt: registers back from the TCB, RFE, jump (399-407).
constexpr u32 kInterruptReturn = 400;
// The pad handler at VBlank after StartPad: both ports polled over SIO, a digital pad in port 1
// and none in port 2 (psyqo teapot: VBlank exit 14536 against 936 for its DMA IRQ).
constexpr u32 kPadPoll = 13600;
// One character through putchar/puts (B0h:3Dh: 5645 per call, 168 calls) and through printf
// (A0h:3Fh: 81105 cycles for 13 characters, 240771 for 37: about 6400 each, formatting included).
constexpr u32 kTtyChar = 5645;
constexpr u32 kPrintfChar = 6400;

// InitPad (B0h:12h: 151,549 and 154,462 cycles, the second with a VBlank inside), StartPad
// (B0h:13h: 2207-2399) and FlushCache (A0h:44h: 8473). The other calls the examples make take
// 50-1600 cycles under OpenBIOS and none here.
constexpr u32 kInitPad = 151549;
constexpr u32 kStartPad = 2300;
constexpr u32 kFlushCache = 8473;

// From power-on to the program's entry point: OpenBIOS hands an EXE over 491,100 cycles before
// the program's first VBlank starts (line 256 of 263, NTSC), 28 lines after the top of the
// frame, whatever the program; the HLE kernel, starting at line 0, would give the program 28
// lines more before its first VBlank. 28 lines of 3413 video cycles at 53.693175 MHz.
constexpr Cycles kBootCycles = Cycles{28} * 3413 * kCpuClockHz / 53693175;

}  // namespace psx::hle_cost
