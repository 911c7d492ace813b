// tackle_embed_rules OUT.cpp RULE.yaml...: a build-time tool. Reads each rule file with
// parse_rule() and writes C++ that makes the same Rule without reading YAML, with the file's
// name and text (a program uses the compiled rule only for that very text: see load_rules).
// A file that does not parse is left out, to be read, and its problems reported, at run time.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "ruleset/ruleset.hpp"

namespace {

using namespace tackle;

// A C++ string literal of any bytes.
std::string literal(std::string_view s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '\\' || c == '"') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n\"\n    \"";
    } else if (c < 0x20 || c >= 0x7f || c == '?') {  // '?': no trigraphs
      char octal[8];
      std::snprintf(octal, sizeof octal, "\\%03o", c);
      out += octal;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string dimension(const Dimension& d) {
  return "Dimension{{" + std::to_string(d.exp[0]) + ", " + std::to_string(d.exp[1]) + ", " + std::to_string(d.exp[2]) +
         "}}";
}

std::string location(const Location& l) {
  return "Location{\"\", " + std::to_string(l.line) + ", " + std::to_string(l.column) + "}";
}

template <class E>
std::string enumerator(const char* type, E e) {
  return "static_cast<" + std::string(type) + ">(" + std::to_string(static_cast<int>(e)) + ")";
}

std::string strings(const std::vector<std::string>& v) {
  std::string out = "{";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + literal(v[i]);
  return out + "}";
}

// The body of a function that returns `r`.
std::string maker(const Rule& r) {
  std::ostringstream os;
  os << "  Rule r;\n";
  os << "  r.type = " << literal(r.type) << ";\n";
  os << "  r.summary = " << literal(r.summary) << ";\n";
  for (int i = 0; i < 3; ++i)
    os << "  r.summary_in[" << i << "] = " << literal(r.summary_in[static_cast<std::size_t>(i)]) << ";\n";
  os << "  r.assumes_direction = " << (r.assumes_direction ? "true" : "false") << ";\n";
  os << "  r.two_bodies = " << literal(r.two_bodies) << ";\n";
  for (const auto& g : r.regimes) {
    os << "  r.regimes.push_back(RegimeSpec{" << literal(g.type) << ", {";
    for (std::size_t i = 0; i < g.args.size(); ++i)
      os << (i ? ", " : "") << "{" << literal(g.args[i].first) << ", " << literal(g.args[i].second) << "}";
    os << "}, " << literal(g.turned) << ", " << literal(g.against) << ", " << literal(g.of) << ", " << location(g.at)
       << "});\n";
  }
  os << "  r.sketch = " << literal(r.sketch) << ";\n";
  for (const auto& a : r.args) {
    os << "  r.args.push_back(ArgSpec{" << literal(a.key) << ", " << enumerator("ArgKind", a.kind) << ", "
       << (a.dimension ? "std::optional<Dimension>(" + dimension(*a.dimension) + ")" : std::string("std::nullopt"))
       << ", " << (a.required ? "true" : "false") << ", " << (a.kind_known ? "true" : "false") << "});\n";
  }
  for (const auto& group : r.one_of) os << "  r.one_of.push_back(" << strings(group) << ");\n";
  for (const auto& u : r.unknowns)
    os << "  r.unknowns.push_back(UnknownSpec{" << literal(u.local) << ", " << literal(u.name_template) << ", "
       << (u.rename_arg ? "std::optional<std::string>(" + literal(*u.rename_arg) + ")" : std::string("std::nullopt"))
       << ", " << dimension(u.dimension) << ", " << literal(u.when) << "});\n";
  for (const auto& l : r.loads)
    os << "  r.loads.push_back(LoadSpec{" << enumerator("LoadSpec::Kind", l.kind) << ", " << literal(l.arg) << ", "
       << literal(l.expr) << ", " << literal(l.at_arg) << ", " << literal(l.couple) << ", " << literal(l.when) << ", "
       << location(l.at) << "});\n";
  for (const auto& c : r.constraints)
    os << "  r.constraints.push_back(ConstraintSpec{" << enumerator("ConstraintSpec::Kind", c.kind) << ", "
       << literal(c.arg) << ", " << literal(c.with) << ", " << literal(c.point) << ", " << location(c.at) << ", "
       << literal(c.along) << "});\n";
  for (const auto& v : r.validity)
    os << "  r.validity.push_back(ValiditySpec{" << literal(v.holds) << ", " << literal(v.meaning) << ", "
       << literal(v.otherwise) << ", " << literal(v.when) << ", " << location(v.at) << "});\n";
  for (const auto& c : r.checks)
    os << "  r.checks.push_back(CheckSpec{" << enumerator("CheckSpec::Kind", c.kind) << ", " << literal(c.arg) << ", "
       << location(c.at) << ", " << literal(c.when) << ", " << literal(c.to) << "});\n";
  for (const auto& a : r.assumptions)
    os << "  r.assumptions.push_back(Assumption{" << literal(a.text) << ", " << literal(a.when) << "});\n";
  os << "  r.dimensions = {";
  for (std::size_t i = 0; i < r.dimensions.size(); ++i) os << (i ? ", " : "") << r.dimensions[i];
  os << "};\n";
  os << "  r.at = " << location(r.at) << ";\n";
  os << "  return r;\n";
  return os.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: tackle_embed_rules OUT.cpp RULE.yaml...\n";
    return 2;
  }
  std::vector<std::filesystem::path> files(argv + 2, argv + argc);
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
  std::ostringstream makers, table;
  int n = 0;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    Rule r;
    try {
      r = parse_rule(text, "");
    } catch (const InputError&) {
      continue;  // read at run time, where its problems are reported
    }
    makers << "Rule make_" << n << "() {\n" << maker(r) << "}\n\n";
    table << "      {" << literal(f.filename().string()) << ",\n       " << literal(text) << ",\n       &make_" << n
          << "},\n";
    ++n;
  }
  std::ostringstream out;
  out << "// Made by tackle_embed_rules (src/ruleset/embed_rules.cpp) from rules/*.yaml at build time.\n"
      << "#include \"ruleset/builtin_rules.hpp\"\n\n#include <optional>\n#include <string>\n\nnamespace tackle "
         "{\n\nnamespace {\n\n"
      << makers.str() << "}  // namespace\n\nstd::span<const BuiltinRule> builtin_rules() {\n";
  if (n == 0)
    out << "  return {};\n";
  else
    out << "  static const BuiltinRule rules[] = {\n" << table.str() << "  };\n  return rules;\n";
  out << "}\n\n}  // namespace tackle\n";
  std::ofstream o(argv[1], std::ios::binary);
  o << out.str();
  return o ? 0 : 1;
}
