// SHA-1 (FIPS 180-4 §6.1), for identifying users' disc images by the hash of their data track,
// the way disc databases name them. Not for security.
#pragma once
#include <array>
#include <cstddef>
#include <string>

#include "core/types.h"

namespace psx {

class Sha1 {
 public:
  Sha1();
  void update(const void* data, size_t n);
  // Finishes the hash (the object is spent) and returns it as 40 lower-case hex digits.
  std::string hex();

 private:
  void block(const u8* p);

  std::array<u32, 5> h_;
  std::array<u8, 64> buf_{};
  size_t used_ = 0;
  u64 length_ = 0;  // bytes hashed
};

}  // namespace psx
