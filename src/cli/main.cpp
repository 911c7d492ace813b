// The tackle command: a thin shell over the library. Exit codes: 0 ok, 1 input error or an
// output that cannot be written, 2 usage error, 3 internal error or out of memory. The options
// are in options.cpp, the commands in commands.cpp and check_command.cpp, what is written
// where in output.cpp.
#include <iostream>
#include <system_error>

#include <CLI/CLI.hpp>
#include <cln/malloc.h>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "report/html.hpp"
#include "ruleset/builtin_rules.hpp"

namespace {

using namespace tackle::cli;

// The subcommand a command line asks for: the first argument that is not an option (nor the
// value of --rules, the one option before it that takes a value), or "" when there is none.
std::string asked_subcommand(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--rules") {
      ++i;
      continue;
    }
    if (!arg.empty() && arg[0] == '-') continue;
    return arg;
  }
  return {};
}

// The command parsed, run; its errors told apart: bad input (1), a broken setup or a bug (3).
int run_command(const Commands& c, const Options& o) {
  try {
    const tackle::RuleSet rules =
        tackle::load_rules(o.rules_dir, tackle::RuleLoading::when_used, tackle::builtin_rules());
    if (c.key->parsed()) return run_key(o, rules);
    if (c.sheet->parsed()) return run_sheet(o, rules);
    if (c.page->parsed()) return run_page(o, rules);
    if (c.isolate->parsed()) return run_isolate(o, rules);
    if (c.sweep->parsed()) return run_sweep(o, rules);
    if (c.simulate->parsed()) return run_simulate(o, rules);
    if (c.check->parsed()) return run_check(o, rules);
    return run_report(o, rules, c.derive->parsed());
  } catch (const tackle::InputError& e) {
    return report_input_error(e);
  } catch (const tackle::InternalError& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  } catch (const tackle::SetupError& e) {
    std::cerr << "tackle: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    // To main, which says so; the outputs unwound on the way have removed their temporary files.
    throw;
  } catch (const std::system_error& e) {
    // A system call that ran out of memory (listing the rules directory under a small address
    // space) is out of memory too, not a bug.
    if (e.code() == std::errc::not_enough_memory) throw std::bad_alloc();
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  }
}

int run(int argc, char** argv) {
  Options o;
  CLI::App app{"tackle: free-body-diagram equations for constrained straight-line motion, solved in closed form"};
  app.require_subcommand(1);
  app.set_version_flag("--version",
                       std::string("tackle ") + TACKLE_VERSION + " (rules: " + tackle::default_rules_dir() + ")");
  app.add_option("--rules", o.rules_dir, "Directory of connection rules (rules/*.yaml)")->capture_default_str();
  const Commands commands = define_commands(app, o, asked_subcommand(argc, argv));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (const int problem = usage_problem(commands, o); problem != 0) return problem;
  return run_command(commands, o);
}

}  // namespace

namespace {

// CLN's allocator reports a failed allocation as a runtime error ("Out of virtual memory."),
// which would read as an internal error: here it is out of memory, std::bad_alloc.
void* cln_allocate(std::size_t size) {
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}

}  // namespace

int main(int argc, char** argv) {
  cln::malloc_hook = cln_allocate;
  int code = 0;
  try {
    code = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::cerr << "tackle: out of memory\n";
    code = 3;
  }
  // Help, version and usage messages go to standard output too: a failed write there is an
  // error whatever the command (exit 1 unless the run had failed already).
  if (!standard_output_written() && code == 0) code = 1;
  return code;
}
