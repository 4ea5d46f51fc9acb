// Pad button names as printed on the controller, mapped to psx-spx's switch bits (pad.h). Shared
// by everything that reads button names from a user's file: input scripts, game integrations.
#pragma once
#include <optional>
#include <string_view>
#include <utility>

#include "core/sio/pad.h"

namespace psx {

inline constexpr std::pair<std::string_view, u16> kPadButtonNames[] = {
    {"up", pad_button::kUp},         {"down", pad_button::kDown},         {"left", pad_button::kLeft},
    {"right", pad_button::kRight},   {"cross", pad_button::kCross},       {"circle", pad_button::kCircle},
    {"square", pad_button::kSquare}, {"triangle", pad_button::kTriangle}, {"l1", pad_button::kL1},
    {"l2", pad_button::kL2},         {"r1", pad_button::kR1},             {"r2", pad_button::kR2},
    {"start", pad_button::kStart},   {"select", pad_button::kSelect},     {"l3", pad_button::kL3},
    {"r3", pad_button::kR3},
};

inline constexpr const char* kPadButtonNameList =
    "up, down, left, right, cross, circle, square, triangle, l1, l2, r1, r2, start, select, l3, r3";

inline std::optional<u16> pad_button_from_name(std::string_view name) {
  for (const auto& [n, bit] : kPadButtonNames)
    if (n == name) return bit;
  return std::nullopt;
}

}  // namespace psx
