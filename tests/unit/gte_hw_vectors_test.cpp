// GTE against 1150 vectors recorded on a real PlayStation (tests/data/gte/gte-hw-vectors.jsonl.gz,
// from JaCzekanski/ps1-tests gte/test-all): register write/read quirks and every command.
// Replays the recording procedure of tests/data/gte/README.md and compares all 64 registers.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/gte/gte.h"
#include "testdata.h"

namespace psx {
namespace {

struct Vector {
  std::string name;
  std::array<u32, 64> input{};
  std::optional<u32> opcode;
  std::array<u32, 64> output{};
};

// Just enough JSON for one line of the file: an object of "name" (string), "input"/"output"
// (arrays of 64 unsigned integers) and "opcode" (unsigned integer or null), in any order.
class LineParser {
 public:
  explicit LineParser(const std::string& s) : s_(s) {}

  std::optional<Vector> parse(std::string& error) {
    Vector v;
    if (!expect('{')) return fail(error, "'{'");
    do {
      std::string key;
      if (!string(key) || !expect(':')) return fail(error, "a key");
      bool ok = true;
      if (key == "name") {
        ok = string(v.name);
      } else if (key == "input") {
        ok = array(v.input);
      } else if (key == "output") {
        ok = array(v.output);
      } else if (key == "opcode") {
        skip_space();
        if (s_.compare(pos_, 4, "null") == 0) {
          pos_ += 4;
        } else {
          u32 op = 0;
          ok = number(op);
          v.opcode = op;
        }
      } else {
        return fail(error, "a known key, not '" + key + "'");
      }
      if (!ok) return fail(error, "the value of '" + key + "'");
    } while (expect(','));
    if (!expect('}')) return fail(error, "'}'");
    return v;
  }

 private:
  std::optional<Vector> fail(std::string& error, const std::string& what) const {
    error = "column " + std::to_string(pos_ + 1) + ": expected " + what;
    return std::nullopt;
  }
  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool expect(char c) {
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != c) return false;
    ++pos_;
    return true;
  }
  bool string(std::string& out) {
    if (!expect('"')) return false;
    const size_t end = s_.find('"', pos_);
    if (end == std::string::npos) return false;
    out = s_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return true;
  }
  bool number(u32& out) {
    skip_space();
    u64 v = 0;
    const size_t start = pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_])) && v <= 0xFFFFFFFF)
      v = v * 10 + u64(s_[pos_++] - '0');
    out = u32(v);
    return pos_ > start && v <= 0xFFFFFFFF;
  }
  bool array(std::array<u32, 64>& out) {
    if (!expect('[')) return false;
    for (size_t i = 0; i < out.size(); ++i) {
      if (i > 0 && !expect(',')) return false;
      if (!number(out[i])) return false;
    }
    return expect(']');
  }

  const std::string& s_;
  size_t pos_ = 0;
};

std::string hex(u32 v) {
  std::ostringstream o;
  o << "0x" << std::hex << v;
  return o.str();
}

TEST(GteHwVectors, AllRecordedVectorsMatch) {
  const auto path = test::testdata_dir() / "gte" / "gte-hw-vectors.jsonl.gz";
  std::istringstream in;
  try {
    in.str(test::read_gz(path));
  } catch (const std::exception& e) {
    FAIL() << e.what();
  }

  std::string line;
  int line_no = 0, vectors = 0, mismatched_vectors = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    std::string error;
    const auto v = LineParser(line).parse(error);
    ASSERT_TRUE(v.has_value()) << path.string() << " line " << line_no << ": " << error;
    ++vectors;

    Gte gte;
    for (u32 r = 0; r < 64; ++r) gte.write_register(r, 0);
    for (u32 r = 0; r < 64; ++r) gte.write_register(r, v->input[r]);
    if (v->opcode) gte.execute(*v->opcode);

    bool mismatch = false;
    for (u32 r = 0; r < 64; ++r) {
      const u32 got = gte.read_register(r);
      if (got == v->output[r]) continue;
      mismatch = true;
      ADD_FAILURE() << v->name << " (opcode " << (v->opcode ? hex(*v->opcode) : "none") << ") register " << r
                    << ": expected " << hex(v->output[r]) << ", got " << hex(got);
    }
    mismatched_vectors += mismatch ? 1 : 0;
  }
  EXPECT_EQ(vectors, 1150) << "the recording has 1150 vectors";
  EXPECT_EQ(mismatched_vectors, 0);
}

}  // namespace
}  // namespace psx
