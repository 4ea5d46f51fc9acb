// `psxrl compat`: one program's run under one kernel (the HLE kernel or a BIOS image), headless,
// and what the report shows of it: whether it booted, how far it ran, what stopped it, and its
// final picture (distinct colours, a hash, a screenshot).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/console.h"

namespace psxrl::cli {

// A program found on the command line: a PS-X EXE or a disc image.
struct CompatProgram {
  enum class Kind { Exe, Disc };
  std::string path;  // as given or found
  std::string name;  // as the report shows it: the argument, or folder/relative path
  Kind kind = Kind::Exe;
};

// The host settings every run shares.
struct CompatSettings {
  std::uint64_t frames = 600;
  bool recompiler = true;
  std::vector<psx::u8> bios;  // empty: the HLE kernel
  std::string bios_name;
};

struct CompatRun {
  // Booted: the program was loaded and started. Unknown for a disc booted by a BIOS, which reads
  // the disc itself (the console does not see when its program starts).
  enum class Booted { Yes, No, Unknown };
  Booted booted = Booted::No;
  std::uint64_t frames = 0;
  // The first thing that stopped the program: the console's fatal error (an unsupported BIOS
  // call, an unhandled exception, a bus error), why it could not boot, or its exit code.
  std::string stop;
  bool failed = false;  // did not boot, or stopped on an error
  bool has_picture = false;
  std::uint32_t width = 0, height = 0;
  std::uint64_t colours = 0;
  std::uint64_t frame_hash = 0;
  // The picture hashes of the run's last frames (up to kCompatTailFrames, oldest first, the last
  // one is frame_hash): what compat_shift() compares when the final pictures differ.
  std::vector<std::uint64_t> tail_hashes;
};

// How many final frames a run keeps the hashes of: one second of NTSC video.
constexpr std::size_t kCompatTailFrames = 60;

// Whether two runs show the same sequence of pictures, one shifted in time: the shift d (run b's
// frame N + d is run a's frame N) with the smallest |d| at which every frame the two tails share
// agrees, the shared part being at least half a tail and holding at least two distinct pictures
// (a still picture proves no shift). Nothing when no such d exists.
std::optional<int> compat_shift(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b);

// Runs `program` for settings.frames frames (less if it stops), counted from the program's start
// (an EXE under a BIOS starts when the BIOS reaches its shell entry, given up to 1200 frames), and,
// when it got as far as a picture, writes that picture as PNG to `screenshot` (an InputError
// names an unwritable file).
CompatRun run_compat(const CompatProgram& program, const CompatSettings& settings, const std::string& screenshot);

// FNV-1a (64-bit) over the picture's size and its RGB888 pixels, and the number of distinct RGB
// values in it: pure functions of the picture, so equal pictures give equal figures.
std::uint64_t picture_hash(const psx::Console::Frame& frame);
std::uint64_t distinct_colours(const psx::Console::Frame& frame);

}  // namespace psxrl::cli
