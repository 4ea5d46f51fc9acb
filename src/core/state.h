// Save-state serialisation: one StateIO object either writes or reads, so each hardware block
// describes its state once in a do_state(StateIO&) method (the DuckStation "DoState" idea).
//
// A block's state is one section: a 4-character tag, the section's version and (since container
// format 2) the byte length of its body, which may hold the sections of the block's parts. Rules
// for changing what a block saves (docs/save-states.md has the whole format):
//   - Any change to the bytes a block writes bumps its version in `section(tag, version, oldest)`.
//   - To keep reading states saved before the change, leave `oldest` at the old version and read
//     the old layout where the version says so: a field added in version N is read with
//     `pod_since(v, N, field, fallback)` (fallback: the value that gives the old behaviour), a
//     field removed or reshaped is read into a local and converted. That code is the block's
//     migration; a unit test loads an old-version section through it.
//   - Raising `oldest` drops support: such states are refused with a message naming the section.
// The lengths let a reader check that each block consumed exactly its own bytes, so a layout
// change without a version bump fails at that block, naming it.
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
  // Container format 1 had sections without lengths; format 2 added them.
  static constexpr u32 kUnsizedSections = 1;
  static constexpr u32 kSizedSections = 2;

  // A writer appends to its own buffer (always with sized sections).
  StateIO() = default;
  // A reader consumes `data` (which must outlive the StateIO), laid out as `format` wrote it.
  StateIO(const u8* data, size_t size, u32 format = kSizedSections)
      : loading_(true), sized_(format >= kSizedSections), in_(data), in_size_(size) {}

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
    std::memcpy(p, take(n), n);
  }
  // Reading: passes over n bytes that the caller knows it holds already (checked as bytes()),
  // and gives where they lie in the state, for a caller that copies part of them.
  const u8* skip(size_t n) { return take(n); }

  // Any trivially copyable value: integers, enums, plain structs, fixed arrays of those.
  template <typename T>
  void pod(T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "pod() needs a trivially copyable type");
    bytes(&v, sizeof(T));
  }

  // A field that a section has from version `since` on. Reading an older section sets it to
  // `fallback` instead: the migration for a field added in a later version.
  template <typename T>
  void pod_since(u32 section_version, u32 since, T& v, const T& fallback) {
    if (section_version >= since)
      pod(v);
    else if (loading_)
      v = fallback;
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

  // A short name: one length byte, then the characters.
  void string(std::string& str) {
    if (!loading_ && str.size() > 255) throw std::logic_error("state string longer than 255 bytes: " + str);
    u8 n = static_cast<u8>(str.size());
    pod(n);
    if (loading_) str.resize(n);
    if (n) bytes(str.data(), n);
  }

  // Opens a block's section and returns its version: `version` when writing; when reading, the
  // version in the state, which must lie in oldest..version (the block's do_state reads older
  // layouts by that number). Every section() is closed by end_section() with the same tag.
  u32 section(const char (&tag)[5], u32 version, u32 oldest = 0) {
    if (oldest == 0) oldest = version;
    char t[4];
    std::memcpy(t, tag, 4);
    u32 v = version, length = 0;
    bytes(t, 4);
    pod(v);
    if (!loading_) {
      open_.push_back(Open{tag, version, out_.size()});
      pod(length);  // patched by end_section
      return version;
    }
    if (std::memcmp(t, tag, 4) != 0) fail(std::string("expected section '") + tag + "'");
    if (v > version)
      fail(std::string("section '") + tag + "' has version " + std::to_string(v) +
           ", newer than this build reads (" + std::to_string(version) + "): the state was made by a newer psxrl");
    if (v < oldest)
      fail(std::string("section '") + tag + "' has version " + std::to_string(v) + ", older than this build reads (" +
           std::to_string(oldest) + " to " + std::to_string(version) + ")");
    size_t end = in_size_;
    if (sized_) {
      pod(length);
      const size_t limit = open_.empty() ? in_size_ : open_.back().end;
      if (length > limit - pos_)
        fail(std::string("section '") + tag + "' claims " + std::to_string(length) + " bytes, " +
             std::to_string(limit - pos_) + " are left");
      end = pos_ + length;
    }
    open_.push_back(Open{tag, v, end});
    return v;
  }

  void end_section(const char (&tag)[5]) {
    if (open_.empty() || open_.back().tag != tag)
      throw std::logic_error(std::string("end_section('") + tag + "') does not close the open section");
    const Open o = open_.back();
    if (!loading_) {
      const u32 length = static_cast<u32>(out_.size() - o.end - 4);
      for (int i = 0; i < 4; ++i) out_[o.end + i] = u8(length >> (8 * i));
    } else if (sized_ && pos_ != o.end) {
      fail("section '" + o.tag + "' version " + std::to_string(o.version) + " has " + std::to_string(o.end - pos_) +
           " bytes this build did not read");
    }
    open_.pop_back();
  }

  // After the last section: every section closed and, when reading, every byte consumed.
  void finish() const {
    if (!open_.empty()) throw std::logic_error("section '" + open_.back().tag + "' was never closed");
    if (loading_ && !at_end()) fail("unexpected bytes after the last section");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw StateError("save state offset " + std::to_string(position()) + ": " + what);
  }

 private:
  struct Open {
    std::string tag;
    u32 version;
    size_t end;  // reading: where the body ends; writing: where its length field is
  };
  // The next n bytes of the input, past the checks that they are there.
  const u8* take(size_t n) {
    const size_t limit = open_.empty() || !sized_ ? in_size_ : open_.back().end;
    if (n > limit - pos_) {
      if (limit == in_size_) fail("state ends early (wanted " + std::to_string(n) + " more bytes)");
      fail("section '" + open_.back().tag + "' version " + std::to_string(open_.back().version) +
           " ends early (wanted " + std::to_string(n) + " more bytes, " + std::to_string(limit - pos_) + " left)");
    }
    const u8* p = in_ + pos_;
    pos_ += n;
    return p;
  }

  bool loading_ = false;
  bool sized_ = true;
  std::vector<u8> out_;
  const u8* in_ = nullptr;
  size_t in_size_ = 0;
  size_t pos_ = 0;
  std::vector<Open> open_;
};

}  // namespace psx
