// The bare GiNaC program tackle is compared with: reads a linear system written by
// bench/scale.py (first line: the unknowns; then one equation `lhs = rhs` per line), solves it
// with lsolve() and puts every value in normal form, as tackle's closed forms are.
// Usage: ginac_lsolve FILE  (prints the number of values and the total length of their text)
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <ginac/ginac.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: ginac_lsolve FILE\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::string line;
  std::getline(in, line);
  GiNaC::parser reader;
  GiNaC::lst unknowns, equations;
  {
    std::istringstream names(line);
    std::string name;
    while (names >> name) unknowns.append(reader(name));
  }
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    equations.append(reader(line.substr(0, eq)) == reader(line.substr(eq + 3)));
  }
  const GiNaC::ex solution = GiNaC::lsolve(equations, unknowns);
  std::size_t length = 0;
  for (std::size_t i = 0; i < solution.nops(); ++i) {
    std::ostringstream text;
    text << GiNaC::normal(solution.op(i).rhs());
    length += text.str().size();
  }
  std::cout << solution.nops() << " values, " << length << " characters\n";
  return solution.nops() == unknowns.nops() ? 0 : 1;
}
