#include "core/files.hpp"

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

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError({{{path, 0, 0}, "is a directory (expected a file)"}});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  return ss.str();
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
