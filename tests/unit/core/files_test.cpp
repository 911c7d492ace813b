#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

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
    for (std::size_t i = 0; i < size; ++i) text += static_cast<char>(i % 7 == 6 ? '\n' : (i % 3 == 0 ? '\0' : 'a' + i % 26));
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
