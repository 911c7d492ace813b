#include "core/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

#include "core/diagnostics.hpp"

namespace tackle {

// Read with the system calls themselves: a stream costs more to set up than a rule file
// costs to read, and every run reads the description and each of the rules.
std::string read_text_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  if (S_ISDIR(st.st_mode)) throw InputError({{{path, 0, 0}, "is a directory (expected a file)"}});
  std::string text;
  text.resize(S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<std::size_t>(st.st_size) + 1 : 4096);
  std::size_t used = 0;
  for (;;) {
    if (used == text.size()) text.resize(2 * text.size());
    const ssize_t n = ::read(fd, text.data() + used, text.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError({{{path, 0, 0}, "cannot read the file"}});
    }
    if (n == 0) break;
    used += static_cast<std::size_t>(n);
  }
  text.resize(used);
  return text;
}

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) {
    error_ = path_ + ": is a directory (expected a file to write)";
    return;
  }
  const std::filesystem::path target(path_);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string pattern = (dir / ("." + target.filename().string() + ".tackle-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    error_ = path_ + ": cannot write the file (" + std::strerror(errno) + ")";
    return;
  }
  // mkstemp makes the file private; give it the mode a new file would have had.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  temp_ = name.data();
  stream_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!stream_) error_ = path_ + ": cannot write the file";
}

AtomicOutput::~AtomicOutput() {
  if (committed_ || temp_.empty()) return;
  stream_.close();
  std::remove(temp_.c_str());
}

bool AtomicOutput::commit() {
  if (!ok()) return false;
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) {
    error_ = path_ + ": cannot write the file";
    return false;
  }
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) {
    error_ = path_ + ": cannot write the file (" + std::strerror(errno) + ")";
    return false;
  }
  committed_ = true;
  return true;
}

bool write_file_atomically(const std::string& path, const std::string& text, std::string& error) {
  AtomicOutput out(path);
  if (out.ok()) out.stream() << text;
  const bool done = out.commit();
  if (!done) error = out.error();
  return done;
}

}  // namespace tackle
