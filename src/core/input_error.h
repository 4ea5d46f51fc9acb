// The error every reader of a user-supplied file throws: it names the file, the position (byte
// offset or line) and what was expected, so front ends can print it and exit with code 2.
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace psx {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;

  static InputError at_offset(const std::string& file, uint64_t offset, const std::string& what) {
    return InputError(file + ": offset " + std::to_string(offset) + ": " + what);
  }
  static InputError at_line(const std::string& file, uint64_t line, const std::string& what) {
    return InputError(file + ":" + std::to_string(line) + ": " + what);
  }
  static InputError whole(const std::string& file, const std::string& what) { return InputError(file + ": " + what); }
};

// Reads a whole file; a missing or unreadable file, or a folder, is an InputError.
inline std::vector<uint8_t> read_file(const std::string& path) {
  // A directory opens as a stream on Linux and fails only at the first read, with libstdc++'s
  // "basic_filebuf::underflow" message: say what is wrong instead.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError::whole(path, "is a folder, expected a file");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError::whole(path, "cannot open file");
  std::vector<uint8_t> data((std::istreambuf_iterator<char>(f)), {});
  if (f.bad()) throw InputError::whole(path, "read error");
  return data;
}

}  // namespace psx
