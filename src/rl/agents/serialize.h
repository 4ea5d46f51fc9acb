// Little-endian byte streams for checkpoints: agents and the trainer write their whole state
// through these, so a checkpoint is one portable blob whose every read is bounds-checked.
#pragma once
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace psxrl::agents {

// A checkpoint that ends early or holds an impossible value; the CLI reports it as bad input.
struct CorruptCheckpoint : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ByteWriter {
 public:
  void u64(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
  void str(const std::string& s) {
    u64(s.size());
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  void f32s(const std::vector<float>& v) {
    u64(v.size());
    for (float f : v) f64(f);
  }
  void u8s(const std::vector<std::uint8_t>& v) {
    u64(v.size());
    bytes_.insert(bytes_.end(), v.begin(), v.end());
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::string take_string() const { return std::string(bytes_.begin(), bytes_.end()); }

 private:
  std::vector<std::uint8_t> bytes_;
};

class ByteReader {
 public:
  ByteReader(const void* data, size_t size, std::string what)
      : p_(static_cast<const std::uint8_t*>(data)), size_(size), what_(std::move(what)) {}
  explicit ByteReader(const std::string& s, std::string what) : ByteReader(s.data(), s.size(), std::move(what)) {}

  std::uint64_t u64() {
    need(8);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p_[pos_ + i]) << (8 * i);
    pos_ += 8;
    return v;
  }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() {
    std::uint64_t bits = u64();
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::string str() {
    std::uint64_t n = u64();
    need(n);
    std::string s(reinterpret_cast<const char*>(p_ + pos_), n);
    pos_ += n;
    return s;
  }
  std::vector<float> f32s() {
    std::uint64_t n = u64();
    need(n * 8);  // each stored as f64; checked before allocating
    std::vector<float> v(n);
    for (auto& f : v) f = static_cast<float>(f64());
    return v;
  }
  std::vector<std::uint8_t> u8s() {
    std::uint64_t n = u64();
    need(n);
    std::vector<std::uint8_t> v(p_ + pos_, p_ + pos_ + n);
    pos_ += n;
    return v;
  }
  // A count that must fit what is left when each item takes at least `min_item_bytes`.
  std::uint64_t count(size_t min_item_bytes) {
    std::uint64_t n = u64();
    if (min_item_bytes && n > (size_ - pos_) / min_item_bytes) fail("a count larger than the data");
    return n;
  }
  bool done() const { return pos_ == size_; }
  [[noreturn]] void fail(const std::string& why) const {
    throw CorruptCheckpoint(what_ + ": byte " + std::to_string(pos_) + ": " + why);
  }

 private:
  void need(std::uint64_t n) const {
    if (n > size_ - pos_) fail("data ends early (truncated)");
  }
  const std::uint8_t* p_;
  size_t size_, pos_ = 0;
  std::string what_;
};

}  // namespace psxrl::agents
