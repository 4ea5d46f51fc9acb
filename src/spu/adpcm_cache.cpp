// Decoded SPU-ADPCM blocks remembered (see adpcm_cache.h).
#include "spu/adpcm_cache.h"

#include <cstring>

namespace psx::spu {

const AdpcmBlockCache::Decoded& AdpcmBlockCache::decode(const u8* ram, u32 address, const AdpcmHistory& history) {
  const u8* block = ram + address;
  u8 wrapped[kAdpcmBlockBytes];
  if (address + kAdpcmBlockBytes > kSoundRamBytes) {  // the last 8 bytes, then the first 8
    std::memcpy(wrapped, block, 8);
    std::memcpy(wrapped + 8, ram, 8);
    block = wrapped;
  }
  u64 low, high;  // the bytes as they lie, in host order: only compared
  std::memcpy(&low, block, 8);
  std::memcpy(&high, block + 8, 8);
  const u32 h = u32(u16(history.old)) | u32(u16(history.older)) << 16;
  Entry& e = entries_[(address / 8) % kEntries];
  if (e.low != low || e.high != high || e.history != h) {
    e.low = low, e.high = high, e.history = h;
    e.out.history = history;
    decode_adpcm_block(block, e.out.history, e.out.samples.data());
  }
  return e.out;
}

}  // namespace psx::spu
