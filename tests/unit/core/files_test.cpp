#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "core/diagnostics.hpp"
#include "core/files.hpp"

using namespace tackle;

namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("tackle-files-test-" + name)).string();
}

}  // namespace

TEST_CASE("Files: a whole file read back as written, empty and past the first buffer", "[files]") {
  for (const std::size_t size : {std::size_t{0}, std::size_t{1}, std::size_t{4096}, std::size_t{10000}}) {
    std::string text;
    for (std::size_t i = 0; i < size; ++i)
      text += static_cast<char>(i % 7 == 6 ? '\n' : (i % 3 == 0 ? '\0' : 'a' + i % 26));
    const std::string path = temp_path(std::to_string(size));
    {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
    CHECK(read_text_file(path) == text);
    std::filesystem::remove(path);
  }
}

TEST_CASE("Files: a directory and a missing file are input errors", "[files]") {
  const std::string dir = std::filesystem::temp_directory_path().string();
  try {
    (void)read_text_file(dir);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).message == "is a directory (expected a file)");
  }
  try {
    (void)read_text_file(temp_path("missing"));
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).message == "cannot read the file");
  }
}

TEST_CASE("Files: reading stops at the size limit, a file of exactly the limit is read", "[files]") {
  const std::string path = temp_path("limit");
  {
    std::ofstream out(path, std::ios::binary);
    out << std::string(10, 'a');
  }
  CHECK(read_text_file(path, 10) == std::string(10, 'a'));
  try {
    (void)read_text_file(path, 9);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(e.diagnostics().at(0).message ==
          "is longer than 9 bytes (expected a description or rule file of at most 9 bytes)");
  }
  std::filesystem::remove(path);
  // A file that never ends stops at the limit (16 MiB), not at the end of memory.
  try {
    (void)read_text_file("/dev/zero");
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(format(e.diagnostics().at(0)) ==
          "/dev/zero: is longer than 16 MiB (expected a description or rule file of at most 16 MiB)");
  }
}

namespace {

// A directory of its own for each test, removed at the end.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name) : path(temp_path(name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::size_t temporaries() const {
    std::size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(path))
      n += e.path().filename().string().find(".tackle-") != std::string::npos;
    return n;
  }
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("Files: an output to a FIFO is written into it, never replaced by a file", "[files]") {
  const TempDir dir("fifo");
  const std::string fifo = (dir.path / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // A reader on the other end, as `tackle ... -o pipe` would have.
  std::string read;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    read = ss.str();
  });
  {
    AtomicOutput out(fifo);
    REQUIRE(out.ok());
    CHECK(out.direct());
    out.stream() << "through the pipe\n";
    CHECK(out.commit());
  }
  reader.join();
  CHECK(read == "through the pipe\n");
  struct stat st {};
  REQUIRE(::stat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(dir.temporaries() == 0);
}

TEST_CASE("Files: -o /dev/null writes to the device and leaves it a character device", "[files]") {
  std::string error;
  CHECK(write_file_atomically("/dev/null", "nothing to keep\n", error));
  CHECK(error.empty());
  struct stat st {};
  REQUIRE(::stat("/dev/null", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
  // A name under /dev that is not there is not made.
  CHECK_FALSE(write_file_atomically("/dev/tackle-no-such-device", "x", error));
  CHECK(error == "/dev/tackle-no-such-device: cannot write the file (No such file or directory)");
  CHECK_FALSE(std::filesystem::exists("/dev/tackle-no-such-device"));
}

TEST_CASE("Files: /dev/shm holds ordinary files: one is replaced whole, as anywhere else", "[files]") {
  if (!std::filesystem::is_directory("/dev/shm")) {
    WARN("no /dev/shm on this machine");
    return;
  }
  const std::string path = "/dev/shm/tackle-files-test-" + std::to_string(::getpid());
  std::string error;
  REQUIRE(write_file_atomically(path, "a longer first version\n", error));
  REQUIRE(write_file_atomically(path, "second\n", error));
  CHECK(slurp(path) == "second\n");  // replaced, not appended to nor written over in place
  std::filesystem::remove(path);
}

TEST_CASE("Files: a write that fails (/dev/full) is an error that says why", "[files]") {
  struct stat st {};
  if (::stat("/dev/full", &st) != 0 || !S_ISCHR(st.st_mode)) {
    WARN("no /dev/full on this machine");
    return;
  }
  std::string error;
  CHECK_FALSE(write_file_atomically("/dev/full", "a line\n", error));
  CHECK(error == "/dev/full: cannot write the file (No space left on device)");
  // Past the buffer too: the first failed write is kept.
  CHECK_FALSE(write_file_atomically("/dev/full", std::string(200000, 'x'), error));
  CHECK(error == "/dev/full: cannot write the file (No space left on device)");
  REQUIRE(::stat("/dev/full", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));
}

TEST_CASE("Files: a symbolic link stays a link, its target is replaced, with its mode", "[files]") {
  const TempDir dir("links");
  const auto target = dir.path / "target.txt";
  std::ofstream(target) << "old\n";
  REQUIRE(::chmod(target.c_str(), 0600) == 0);
  std::filesystem::create_directories(dir.path / "sub");
  const auto link = dir.path / "sub" / "link.txt";
  std::filesystem::create_symlink("../target.txt", link);  // relative: to the link's directory
  std::string error;
  REQUIRE(write_file_atomically(link.string(), "new\n", error));
  CHECK(std::filesystem::is_symlink(link));
  CHECK(std::filesystem::read_symlink(link) == "../target.txt");
  CHECK(slurp(target) == "new\n");
  struct stat st {};
  REQUIRE(::stat(target.c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == 0600);
  CHECK(dir.temporaries() == 0);
  // A link to a file that is not there yet makes that file, and stays a link.
  const auto dangling = dir.path / "dangling.txt";
  std::filesystem::create_symlink("made.txt", dangling);
  REQUIRE(write_file_atomically(dangling.string(), "made\n", error));
  CHECK(std::filesystem::is_symlink(dangling));
  CHECK(slurp(dir.path / "made.txt") == "made\n");
  // A new file has the mode the umask gives (0666 without its bits).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  REQUIRE(write_file_atomically((dir.path / "fresh.txt").string(), "x", error));
  REQUIRE(::stat((dir.path / "fresh.txt").c_str(), &st) == 0);
  CHECK((st.st_mode & 07777) == (0666 & ~mask));
  // A cycle of links is an error, and nothing is written.
  std::filesystem::create_symlink("b", dir.path / "a");
  std::filesystem::create_symlink("a", dir.path / "b");
  CHECK_FALSE(write_file_atomically((dir.path / "a").string(), "x", error));
  CHECK(error == (dir.path / "a").string() + ": cannot write the file (Too many levels of symbolic links)");
}
