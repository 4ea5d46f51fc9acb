// Fuzzes memory cards (src/core/sio/memory_card.h): the image file a user supplies, the card's
// saved state, and the command bytes the guest sends it. Input layout:
//   byte 0 flags: bit 0 = back the card with an image file, bit 1 = pad/cut that image to the
//                 128 KiB a card holds (so the card loads it), bit 2 = load a card state
//   [bit 0] u16 length + image bytes
//   [bit 2] u16 length + bytes over the first fields of the card state after its 128 KiB of data
//   the rest: bytes sent to the card while selected, deselected after each command's last byte
#include <memory>

#include "core/sio/memory_card.h"
#include "fuzz_util.h"

using psx::MemoryCard;

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  psxfuzz::Reader in(data, size);
  const psx::u8 flags = in.byte();
  std::unique_ptr<MemoryCard> card;
  if (flags & 1) {
    size_t n = in.u16();
    std::vector<psx::u8> image;
    while (n-- && !in.empty()) image.push_back(in.byte());
    if (flags & 2) image.resize(MemoryCard::kSize, 0);
    const auto path = psxfuzz::scratch_dir() / "card.mcd";
    psxfuzz::write_file(path, image.data(), image.size());
    try {
      card = std::make_unique<MemoryCard>(path);
    } catch (const psx::MemoryCardError&) {
      return 0;
    }
  } else {
    card = std::make_unique<MemoryCard>();
  }
  if (flags & 4) {
    // A real state of this card, its small fields after the image replaced by the input.
    psx::StateIO writer;
    card->do_state(writer);
    std::vector<psx::u8> state = writer.buffer();
    const size_t fields = 12 + MemoryCard::kSize;  // section tag, version and length, then the image
    const size_t end = fields + std::min<size_t>(in.u16(), state.size() - fields);
    for (size_t i = fields; i < end; ++i) state[i] = in.byte();
    psx::StateIO reader(state.data(), state.size());
    try {
      card->do_state(reader);
    } catch (const psx::StateError&) {
      return 0;  // a console restores its previous state after a refused load (Console::load_state)
    }
  }
  while (!in.empty())
    if (!card->transfer(in.byte()).ack) card->deselect();
  return 0;
}
