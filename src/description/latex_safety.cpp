// The LaTeX safety of a description's texts (see latex_safety.hpp).
#include "description/latex_safety.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace tackle {

namespace {

// Text that goes into LaTeX as LaTeX: a statement (prose with $math$) and a `tex:` name. A
// description is the instructor's, but the sheets and keys made from it are compiled by
// others, often by a script, and LaTeX reads and writes files (`\input{/etc/passwd}` prints
// the file into the sheet). So such text may not use a command that reads or writes files,
// runs programs, defines commands or changes how LaTeX reads characters (which can spell
// any of them): not a sandbox (compile sheets with openin_any=p and without shell escape),
// but no sheet made by tackle asks LaTeX to do any of it. See docs/grading.md.
bool forbidden_control_word(const std::string& word) {
  static const std::set<std::string> exact{"def",
                                           "edef",
                                           "gdef",
                                           "xdef",
                                           "let",
                                           "glet",
                                           "futurelet",
                                           "newcommand",
                                           "renewcommand",
                                           "providecommand",
                                           "DeclareRobustCommand",
                                           "NewDocumentCommand",
                                           "RenewDocumentCommand",
                                           "ProvideDocumentCommand",
                                           "DeclareDocumentCommand",
                                           "newenvironment",
                                           "renewenvironment",
                                           "usepackage",
                                           "RequirePackage",
                                           "documentclass",
                                           "LoadClass",
                                           "immediate",
                                           "special",
                                           "scantokens",
                                           "scantextokens",
                                           "makeatletter",
                                           "ExplSyntaxOn",
                                           "directlua",
                                           "latelua",
                                           "luaexec",
                                           "luadirect",
                                           "ShellEscape",
                                           "import",
                                           "subimport",
                                           "subfile",
                                           "bibliography",
                                           "addbibresource",
                                           "everyeof",
                                           "uccode",
                                           "lccode",
                                           "endlinechar",
                                           "newlinechar"};
  if (exact.count(word)) return true;
  std::string lower;
  for (char c : word) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  // Whole families: \input, \include, \openin, \openout, \read, \readline, \write, \write18,
  // \InputIfFileExists, \verbatiminput, \lstinputlisting, \includegraphics, \pdffiledump,
  // \csname, \ifcsname, \catcode, \pdfobj, \pdfximage, ...
  for (const char* part : {"input", "include", "open", "read", "write", "file", "csname", "catcode"})
    if (lower.find(part) != std::string::npos) return true;
  return lower.rfind("pdf", 0) == 0;
}

// `\begin{filecontents}` writes a file, `\begin{VerbatimOut}` too: environments by the same
// families.
bool forbidden_environment(const std::string& name) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* part : {"input", "include", "open", "read", "write", "file", "out", "lua", "shell"})
    if (lower.find(part) != std::string::npos) return true;
  return false;
}

// Where `needle` is first written in the file at or after `from` (a byte offset), as a
// location; `fallback` when it is not there as typed (a quoted scalar's escapes spell it).
Location locate_in_source(const std::string& source, std::size_t& from, const std::string& needle,
                          const Location& fallback) {
  std::size_t at = source.find(needle, from);
  if (at == std::string::npos) return fallback;
  from = at + needle.size();
  if (at > 0 && source[at - 1] == '\\') --at;  // "\\input" in a double-quoted scalar: its first backslash
  const std::size_t line_start = source.rfind('\n', at) == std::string::npos ? 0 : source.rfind('\n', at) + 1;
  int line = 1, column = 1;
  for (std::size_t i = 0; i < line_start; ++i) line += source[i] == '\n';
  for (std::size_t i = line_start; i < at; ++i)
    column += (static_cast<unsigned char>(source[i]) & 0xC0) != 0x80;  // characters, as libyaml counts
  return {fallback.file, line, column};
}

// The byte offset of a location (line and column, as libyaml counts characters).
std::size_t offset_of(const std::string& source, const Location& at) {
  std::size_t i = 0;
  for (int line = 1; line < at.line && i < source.size(); ++i)
    if (source[i] == '\n') ++line;
  for (int column = 1; column < at.column && i < source.size(); ++column) do
      ++i;
    while (i < source.size() && (static_cast<unsigned char>(source[i]) & 0xC0) == 0x80);
  return i;
}

void check_latex(const std::string& source, const Text& t, const std::string& what, Diagnostics& diags) {
  const std::string expected =
      " (expected LaTeX that reads and writes no files: no \\input, \\include, \\openin, \\write, \\read, "
      "\\catcode, \\def, \\usepackage, ^^, ...; see docs/grading.md)";
  std::size_t from = t.at.line > 0 ? offset_of(source, t.at) : 0;
  const std::string& s = t.text;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '^' && i + 1 < s.size() && s[i + 1] == '^') {
      // ^^69 is i, ^^5c a backslash: TeX reads them before it sees any command.
      diags.error(locate_in_source(source, from, "^^", t.at), "^^ in " + what + " is not allowed" + expected);
      return;
    }
    if (s[i] != '\\') continue;
    std::size_t j = i + 1;
    while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
    if (j == i + 1) {
      ++i;  // a control symbol (\\, \$, \{): never a command by name
      continue;
    }
    const std::string word = s.substr(i + 1, j - i - 1);
    std::string shown = "\\" + word;
    bool bad = forbidden_control_word(word);
    if (!bad && word == "begin") {
      std::size_t k = j;
      while (k < s.size() && s[k] == ' ') ++k;
      const std::size_t close = k < s.size() && s[k] == '{' ? s.find('}', k) : std::string::npos;
      if (close != std::string::npos && forbidden_environment(s.substr(k + 1, close - k - 1))) {
        bad = true;
        shown = "\\begin{" + s.substr(k + 1, close - k - 1) + "}";
      }
    }
    if (bad) {
      diags.error(locate_in_source(source, from, "\\" + word, t.at),
                  shown + " in " + what + " is not allowed" + expected);
      return;  // one per text: the rest may follow from it
    }
    i = j - 1;
  }
}

// The texts of a description that reach LaTeX, HTML and Markdown: a title (and a phase's
// name, part of its title) on one line, since a blank line in \section*{...} ends the
}  // namespace

// paragraph inside it and breaks the document; statements and TeX names as above.
void check_texts(const std::string& source, const Description& d, Diagnostics& diags) {
  if (d.title.text.find_first_of("\r\n") != std::string::npos)
    diags.error(d.title.at, "'title' has a line break (expected a one-line title)");
  if (d.statement) check_latex(source, *d.statement, "'statement'", diags);
  for (const auto& p : d.parameters)
    if (p.tex) {
      check_latex(source, *p.tex, "'tex' of parameter '" + p.name.text + "'", diags);
      if (p.tex->text.find_first_of("<>\r\n") != std::string::npos)
        diags.error(p.tex->at,
                    "'tex' of parameter '" + p.name.text +
                        "' has '<', '>' or a line break (expected one line of LaTeX math; \\lt and \\gt for < and >)");
    }
  for (const auto& f : d.find)
    if (f.tex) {
      check_latex(source, *f.tex, "'tex' of '" + f.name.text + "' in 'find'", diags);
      if (f.tex->text.find_first_of("<>\r\n") != std::string::npos)
        diags.error(f.tex->at, "'tex' of '" + f.name.text +
                                   "' in 'find' has '<', '>' or a line break (expected one line of LaTeX math; \\lt "
                                   "and \\gt for < and >)");
    }
}

}  // namespace tackle
