// Save-state serialisation: one StateIO object either writes or reads, so each hardware block
// describes its state once in a do_state(StateIO&) method (the DuckStation "DoState" idea).
#pragma once
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/types.h"

namespace psx {

// Thrown when a state blob is truncated, corrupt or of another version. Carries the byte offset.
class StateError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StateIO {
 public:
  // A writer appends to its own buffer.
  StateIO() = default;
  // A reader consumes `data` (which must outlive the StateIO).
  StateIO(const u8* data, size_t size) : loading_(true), in_(data), in_size_(size) {}

  bool loading() const { return loading_; }
  const std::vector<u8>& buffer() const { return out_; }
  size_t position() const { return loading_ ? pos_ : out_.size(); }
  bool at_end() const { return pos_ == in_size_; }

  void bytes(void* p, size_t n) {
    if (!loading_) {
      const u8* b = static_cast<const u8*>(p);
      out_.insert(out_.end(), b, b + n);
      return;
    }
    if (n > in_size_ - pos_) fail("state ends early (wanted " + std::to_string(n) + " more bytes)");
    std::memcpy(p, in_ + pos_, n);
    pos_ += n;
  }

  // Any trivially copyable value: integers, enums, plain structs, fixed arrays of those.
  template <typename T>
  void pod(T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "pod() needs a trivially copyable type");
    bytes(&v, sizeof(T));
  }

  void boolean(bool& b) {
    u8 v = b ? 1 : 0;
    pod(v);
    if (loading_ && v > 1) fail("bad boolean value " + std::to_string(v));
    b = v != 0;
  }

  template <typename T>
  void vec(std::vector<T>& v, size_t max_elems) {
    u32 n = static_cast<u32>(v.size());
    pod(n);
    if (loading_) {
      if (n > max_elems) fail("element count " + std::to_string(n) + " exceeds " + std::to_string(max_elems));
      v.resize(n);
    }
    if (n) bytes(v.data(), n * sizeof(T));
  }

  // Every block starts its state with a 4-character tag and a version: a reader checks both,
  // so a blob from another build or a shuffled blob fails here, naming the block.
  void section(const char (&tag)[5], u32 version) {
    char t[4];
    std::memcpy(t, tag, 4);
    u32 v = version;
    bytes(t, 4);
    pod(v);
    if (!loading_) return;
    if (std::memcmp(t, tag, 4) != 0) fail(std::string("expected section '") + tag + "'");
    if (v != version)
      fail(std::string("section '") + tag + "' has version " + std::to_string(v) + ", this build reads " +
           std::to_string(version));
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw StateError("save state offset " + std::to_string(position()) + ": " + what);
  }

 private:
  bool loading_ = false;
  std::vector<u8> out_;
  const u8* in_ = nullptr;
  size_t in_size_ = 0;
  size_t pos_ = 0;
};

}  // namespace psx
