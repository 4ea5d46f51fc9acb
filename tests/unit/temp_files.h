// Checks for temporary files left by psx::write_file_atomically (src/core/atomic_file.h), which
// names them after the target: TARGET.tmp.PID.N, next to it; and a way to make writes fail part-way.
#pragma once
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <string>

namespace psx::test {

inline bool temporary_files_left(const std::filesystem::path& target) {
  const std::string prefix = target.filename().string() + ".tmp";
  std::filesystem::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) return true;
  return false;
}

// Makes this process's writes past `bytes` of a file fail with EFBIG (instead of a SIGXFSZ
// signal): a failure in the middle of writing that binds root too. For a child process (a death
// test); returns false when the limit cannot be set. `previous` receives the old limit.
inline bool limit_file_size(rlim_t bytes, rlimit& previous) {
  std::signal(SIGXFSZ, SIG_IGN);
  if (::getrlimit(RLIMIT_FSIZE, &previous) != 0) return false;
  rlimit small = previous;
  small.rlim_cur = bytes;
  return ::setrlimit(RLIMIT_FSIZE, &small) == 0;
}

}  // namespace psx::test
