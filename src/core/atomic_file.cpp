// Atomic file writing: exclusive temporary file, write, fsync, rename, directory fsync.
#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace psx {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  throw std::runtime_error(path + ": " + what + ": " + std::strerror(err));
}

// Creates a temporary file next to `path` that no other writer has: O_EXCL refuses a name that
// exists, so a collision (another thread of this process, or a stale file) moves on to the next.
int create_temporary(const std::string& path, std::string& tmp) {
  const std::string stem = path + ".tmp." + std::to_string(::getpid()) + ".";
  for (unsigned n = 0; n < 10000; ++n) {
    tmp = stem + std::to_string(n);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail(path, "cannot create the temporary file " + tmp, errno);
  }
  fail(path, "cannot create a temporary file (" + stem + "0 to 9999 all exist)", EEXIST);
}

bool write_all(int fd, const u8* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= size_t(n);
  }
  return true;
}

// After a rename, the directory entry reaches the disk only when the directory is synced. A
// failure here leaves the new file complete and in place, so it is not reported.
void sync_directory(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// The process id in a temporary file's name "<target>.tmp.PID.N", or 0 when the name is not one.
pid_t temporary_owner(const std::string& name) {
  const size_t at = name.rfind(".tmp.");
  if (at == std::string::npos || at == 0) return 0;
  const size_t dot = name.find('.', at + 5);
  if (dot == std::string::npos || dot == at + 5 || dot + 1 == name.size()) return 0;
  const std::string pid = name.substr(at + 5, dot - at - 5), n = name.substr(dot + 1);
  if (pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos ||
      n.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return static_cast<pid_t>(std::stol(pid));
}

// A process killed while writing leaves its temporary file behind, and nothing else would ever
// remove it: the next writer into that folder removes those of processes that no longer exist
// (kill(pid, 0) fails with ESRCH). A live process's files, this one's included, are left alone.
void remove_stale_temporaries(const std::string& path) {
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = temporary_owner(it->path().filename().string());
    if (owner <= 0 || owner == ::getpid()) continue;
    if (::kill(owner, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;  // another writer may remove it first
    std::filesystem::remove(it->path(), ignored);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const u8* data, size_t size) {
  remove_stale_temporaries(path);
  std::string tmp;
  const int fd = create_temporary(path, tmp);
  bool ok = write_all(fd, data, size) && ::fsync(fd) == 0;
  int err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) ok = false, err = errno;
  if (!ok) {
    ::unlink(tmp.c_str());
    fail(path, "write failed", err);
  }
  sync_directory(path);
}

void write_file_atomically(const std::string& path, const std::vector<u8>& data) {
  write_file_atomically(path, data.data(), data.size());
}

}  // namespace psx
