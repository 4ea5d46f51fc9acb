// Fixed-width integer aliases and the cycle type shared by every hardware block.
#pragma once
#include <cstddef>
#include <cstdint>

namespace psx {

using u8 = std::uint8_t;
using u16 = std::uint16_t;
using u32 = std::uint32_t;
using u64 = std::uint64_t;
using s8 = std::int8_t;
using s16 = std::int16_t;
using s32 = std::int32_t;
using s64 = std::int64_t;

// CPU clock cycles (33.8688 MHz). The whole console runs on this one timeline.
using Cycles = std::uint64_t;

constexpr u32 kCpuClockHz = 33868800;

}  // namespace psx
