// SPU RAM transfers (psx-spx "SPU Memory Access"): the 32-halfword data FIFO for manual writes,
// DMA channel 4 reads and writes at the transfer address, and the RAM IRQ address check
// ("SPU Interrupt") that every transfer access goes through.
#include "spu/spu.h"

namespace psx {

void Spu::raise_irq() {
  if (irq_flag_) return;  // the line stays asserted until acknowledged through ATTR bit 6
  irq_flag_ = true;
  irq_.raise(Irq::Spu);
}

void Spu::ram_write16(u32 byte_addr, u16 value) {
  check_irq(byte_addr);
  if (reverb_.owes()) reverb_.settle(ram_.data());  // they read sound RAM as it was
  byte_addr &= kRamSize - 2;
  ram_[byte_addr] = static_cast<u8>(value);
  ram_[byte_addr + 1] = static_cast<u8>(value >> 8);
}

u16 Spu::ram_read16(u32 byte_addr) {
  check_irq(byte_addr);
  byte_addr &= kRamSize - 2;
  return static_cast<u16>(ram_[byte_addr] | ram_[byte_addr + 1] << 8);
}

void Spu::fifo_push(u16 value) {
  // In manual-write mode the FIFO drains into RAM as it fills; otherwise it holds up to 32
  // halfwords until that mode is selected, and further writes are lost.
  if (transfer_mode() == TransferMode::ManualWrite) {
    ram_write16(transfer_addr_, value);
    transfer_addr_ = (transfer_addr_ + 2) & (kRamSize - 1);
    return;
  }
  if (fifo_count_ < kFifoSize) fifo_[fifo_count_++] = value;
}

void Spu::flush_fifo() {
  for (u32 i = 0; i < fifo_count_; ++i) {
    ram_write16(transfer_addr_, fifo_[i]);
    transfer_addr_ = (transfer_addr_ + 2) & (kRamSize - 1);
  }
  fifo_count_ = 0;
}

void Spu::dma_write(const u32* words, u32 count) {
  sync();  // samples due first: they read the RAM and write its capture buffers
  for (u32 i = 0; i < count; ++i) {
    ram_write16(transfer_addr_, static_cast<u16>(words[i]));
    ram_write16(transfer_addr_ + 2, static_cast<u16>(words[i] >> 16));
    transfer_addr_ = (transfer_addr_ + 4) & (kRamSize - 1);
  }
}

void Spu::dma_read(u32* words, u32 count) {
  sync();
  for (u32 i = 0; i < count; ++i) {
    const u32 lo = ram_read16(transfer_addr_);
    const u32 hi = ram_read16(transfer_addr_ + 2);
    words[i] = lo | hi << 16;
    transfer_addr_ = (transfer_addr_ + 4) & (kRamSize - 1);
  }
}

bool Spu::dma_request() const {
  // Only ATTR decides, and samples never change ATTR: no sync needed.
  const TransferMode m = transfer_mode();
  return m == TransferMode::DmaWrite || m == TransferMode::DmaRead;
}

// DMA words pass through the 32-halfword data FIFO, which sound RAM takes at 16 CPU cycles a
// halfword (DuckStation's TRANSFER_TICKS_PER_HALFWORD): the next block is asked for once it has
// drained. ps1-tests `spu/memory-transfer` expects 16 cycles a byte, within -90%/+10%, and lets
// the CPU run between the blocks; the console passes it.
Cycles Spu::dma_block_cycles(u32 words) const { return Cycles{32} * words; }

}  // namespace psx
