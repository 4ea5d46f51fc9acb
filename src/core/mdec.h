// Macroblock decoder (psx-spx "Macroblock Decoder (MDEC)"): MDEC0 command/parameter and data
// register at 0x1F801820, MDEC1 control/status at 0x1F801824. Commands: decode macroblocks (1),
// set quant tables (2), set scale table (3); others do nothing. Compressed data arrives on DMA0
// (MDECin), pixels leave on DMA1 (MDECout) as 4/8-bit mono or 15/24-bit colour. Decoding is
// instantaneous here: one macroblock is decoded whenever the output is empty and its data is in.
#pragma once
#include <vector>

#include "core/io_device.h"
#include "core/mdec_decode.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Mdec : public IoDevice {
 public:
  static constexpr u32 kBase = 0x1F801820;
  static constexpr u32 kSize = 16;

  Mdec();

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  // The device sides of DMA channel 0 (MDECin) and 1 (MDECout).
  DmaPort& dma_in() { return in_port_; }
  DmaPort& dma_out() { return out_port_; }

  u32 status() const;

  void do_state(StateIO& s);

 private:
  class InPort : public DmaPort {
   public:
    explicit InPort(Mdec& m) : m_(m) {}
    void dma_write(const u32* words, u32 count) override;
    void dma_read(u32* words, u32 count) override;
    bool dma_request() const override { return m_.data_in_request(); }

   private:
    Mdec& m_;
  };
  class OutPort : public DmaPort {
   public:
    explicit OutPort(Mdec& m) : m_(m) {}
    void dma_write(const u32* words, u32 count) override {}  // MDECout only reads
    void dma_read(u32* words, u32 count) override;
    bool dma_request() const override { return m_.data_out_request(); }

   private:
    Mdec& m_;
  };
  enum class Command : u32 { None = 0, Decode = 1, SetQuant = 2, SetScale = 3 };

  bool data_in_request() const { return enable_in_ && command_ != Command::None && remaining_ > 0; }
  bool data_out_request() const { return enable_out_ && output_pos_ < output_.size(); }

  void write_word(u32 word);
  void start_command(u32 word);
  void apply_tables();
  // Decodes the next macroblock when the output is empty; ends the command when nothing is left.
  void decode_available();
  bool decode_macroblock();
  void pack_colour(const mdec::Rgb16x16& rgb);
  void pack_mono(const mdec::Samples& y);
  u32 read_data(bool dma_order);
  void reset();

  u32 depth() const { return (command_word_ >> 27) & 3; }  // 0=4bit 1=8bit 2=24bit 3=15bit

  InPort in_port_{*this};
  OutPort out_port_{*this};
  Command command_ = Command::None;
  u32 command_word_ = 0;   // bits 25-28 are reflected in status bits 23-26
  u32 remaining_ = 0;      // parameter words still expected
  u16 idle_low_ = 0xFFFF;  // status bits 0-15 when no command is running
  bool enable_in_ = false;
  bool enable_out_ = false;
  std::vector<u16> input_;  // parameter halfwords of the running command
  size_t input_pos_ = 0;
  std::vector<u32> output_;  // one decoded macroblock in DMA1 (row-major) word order
  size_t output_pos_ = 0;
  mdec::QuantTable iq_y_{};
  mdec::QuantTable iq_uv_{};
  mdec::ScaleTable scale_{};
};

}  // namespace psx
