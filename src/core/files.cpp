#include "core/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <vector>

#include "core/diagnostics.hpp"

namespace tackle {

// Read with the system calls themselves: a stream costs more to set up than a rule file
// costs to read, and every run reads the description and each of the rules.
std::string read_text_file(const std::string& path, std::size_t max_bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  if (S_ISDIR(st.st_mode)) throw InputError({{{path, 0, 0}, "is a directory (expected a file)"}});
  auto too_long = [&] {
    const std::string mib =
        max_bytes % (1 << 20) == 0 ? std::to_string(max_bytes >> 20) + " MiB" : std::to_string(max_bytes) + " bytes";
    return InputError(
        {{{path, 0, 0}, "is longer than " + mib + " (expected a description or rule file of at most " + mib + ")"}});
  };
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > max_bytes) throw too_long();
  std::string text;
  text.resize(S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<std::size_t>(st.st_size) + 1 : 4096);
  std::size_t used = 0;
  for (;;) {
    // One byte past the bound tells a file of exactly max_bytes from a longer one.
    if (used > max_bytes) throw too_long();
    if (used == text.size()) text.resize(std::min(2 * text.size(), max_bytes + 1));
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

std::unique_ptr<std::istream> open_text_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError({{{path, 0, 0}, "is a directory (expected a file)"}});
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) throw InputError({{{path, 0, 0}, "cannot read the file"}});
  return in;
}

bool FdBuffer::write_all(const char* s, std::size_t n) {
  if (error_ != 0) return false;
  while (n > 0) {
    const ssize_t w = ::write(fd_, s, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      error_ = errno;
      return false;
    }
    s += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool FdBuffer::drain() {
  const bool done = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
  setp(buffer_, buffer_ + sizeof buffer_);
  return done;
}

FdBuffer::int_type FdBuffer::overflow(int_type c) {
  if (!drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int FdBuffer::sync() { return drain() ? 0 : -1; }

std::streamsize FdBuffer::xsputn(const char* s, std::streamsize n) {
  const auto room = static_cast<std::streamsize>(epptr() - pptr());
  if (n <= room) {
    std::memcpy(pptr(), s, static_cast<std::size_t>(n));
    pbump(static_cast<int>(n));
    return n;
  }
  if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
  return n;
}

namespace {

// The temporary files of this process that a signal must not leave behind. The handler may
// only use what is async-signal-safe: fixed storage, lock-free atomics, unlink and raise.
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 armed
  char path[4096];
};
Slot temporaries[16];

extern "C" void remove_temporaries(int signal) {
  for (auto& s : temporaries)
    if (s.state.load() == 2) ::unlink(s.path);
  // SA_RESETHAND restored the default action: the signal, raised again, ends the process as
  // it would have without tackle's handler (a shell sees "killed by SIGTERM").
  ::raise(signal);
}

// Installed once, and only for a signal whose action is still the default: a process that
// ignores SIGHUP (nohup) keeps ignoring it, and a host with its own SIGINT handler (Python
// importing the module) keeps its own.
void install_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || (old.sa_flags & SA_SIGINFO) || old.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = remove_temporaries;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESETHAND;
      (void)::sigaction(sig, &action, nullptr);
    }
  });
}

// The slot holding `path`, or -1 when every slot is taken or the path does not fit (the file
// is then removed by the destructor only, as before).
int register_temporary(const std::string& path) {
  if (path.size() >= sizeof(Slot::path)) return -1;
  install_handler();
  for (int i = 0; i < static_cast<int>(std::size(temporaries)); ++i) {
    int free = 0;
    if (!temporaries[i].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(temporaries[i].path, path.c_str(), path.size() + 1);
    temporaries[i].state.store(2);
    return i;
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) temporaries[slot].state.store(0);
}

// /dev and /proc hold devices and the process's own descriptors (/dev/stdout, /dev/fd/1,
// /proc/self/fd/1), not files to make or replace; /dev/shm is an ordinary directory of files.
bool under_system_directory(const std::string& path) {
  return (path.rfind("/dev/", 0) == 0 && path.rfind("/dev/shm/", 0) != 0) || path.rfind("/proc/", 0) == 0;
}

// `path` with its symbolic links followed, as far as they lead (a link to a file that does
// not exist yet leads to that file); "" with errno ELOOP for a cycle. `system` is set when
// the path or a link on the way lies under /dev or /proc, whose links (/dev/stdout ->
// /proc/self/fd/1 -> "pipe:[1234]") are not paths to make files beside.
std::string follow_links(std::string path, bool& system) {
  namespace fs = std::filesystem;
  system = under_system_directory(path);
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return path;
    std::vector<char> link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4095) + 1);
    const ssize_t n = ::readlink(path.c_str(), link.data(), link.size());
    if (n < 0 || static_cast<std::size_t>(n) >= link.size()) return path;
    const fs::path to(std::string(link.data(), static_cast<std::size_t>(n)));
    path = (to.is_absolute() ? to : fs::path(path).parent_path() / to).string();
    system = system || under_system_directory(path);
  }
  errno = ELOOP;
  return {};
}

}  // namespace

void AtomicOutput::fail(int err) {
  error_ =
      path_ + ": cannot write the file" + (err != 0 ? std::string(" (") + std::strerror(err) + ")" : std::string());
}

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;  // the link's target, for a link
  if (exists && S_ISDIR(st.st_mode)) {
    error_ = path_ + ": is a directory (expected a file to write)";
    return;
  }
  bool system = false;
  target_ = follow_links(path_, system);
  if (target_.empty()) {
    fail(errno);
    return;
  }
  // Not a regular file, or a name under /dev or /proc: written where it is, never replaced
  // and never made (no O_CREAT: `-o /dev/nul` is an error, not a new file in /dev). Appended
  // to, so that `/dev/stdout` redirected to a file adds to what is there.
  if ((exists && !S_ISREG(st.st_mode)) || system) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) {
      fail(errno);
      return;
    }
  } else {
    const std::filesystem::path target(target_);
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    std::string pattern = (dir / ("." + target.filename().string() + ".tackle-XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ < 0) {
      fail(errno);
      return;
    }
    // Out of memory from here to the end of the constructor would skip the destructor: the
    // file just made is removed before the exception goes on.
    try {
      temp_ = name.data();
      buffer_ = std::make_unique<FdBuffer>(fd_);
    } catch (...) {
      ::unlink(name.data());
      ::close(fd_);
      fd_ = -1;
      throw;
    }
    slot_ = register_temporary(temp_);
    // mkstemp makes the file private; give it the old file's mode and owner (a 0600 file
    // stays 0600; the owner can only be kept by root), or the mode a new file would have had.
    if (exists) {
      (void)::fchmod(fd_, st.st_mode & 07777);
      if (::geteuid() == 0) (void)::fchown(fd_, st.st_uid, st.st_gid);
    } else {
      const mode_t mask = ::umask(0);
      ::umask(mask);
      (void)::fchmod(fd_, 0666 & ~mask);
    }
  }
  if (!buffer_) buffer_ = std::make_unique<FdBuffer>(fd_);
  stream_.rdbuf(buffer_.get());
}

AtomicOutput::~AtomicOutput() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
  unregister_temporary(slot_);
}

bool AtomicOutput::commit() {
  if (!ok()) return false;
  stream_.flush();
  const int fd = fd_;
  fd_ = -1;
  if (!stream_ || buffer_->error() != 0) {
    fail(buffer_->error());
    ::close(fd);
    return false;
  }
  // close() can be the first to report a failed write (NFS, a full disk with delayed
  // allocation).
  if (::close(fd) != 0) {
    fail(errno);
    return false;
  }
  if (!temp_.empty() && std::rename(temp_.c_str(), target_.c_str()) != 0) {
    fail(errno);
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
