#!/usr/bin/env bash
# cmake --install into a temporary prefix: the installed program runs (--version, derive of an
# example, the rules found beside it after the prefix is moved), and a program built against
# the installed CMake package derives a problem.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
"$work/prefix/bin/tackle" --version | grep -q "^tackle [0-9.]* (rules: $work/prefix/share/tackle/rules)$"
"$work/prefix/bin/tackle" solve "$source/examples/atwood-machine.yaml" | grep -q "^T = 2\*g\*m_A\*m_B/(m_A + m_B)  = 36.7875 N$"
# The man pages: tackle(1) and one per command (each command of --help has its page), each
# rendered by groff with every warning on and none given (groff-base is installed by scripts/setup).
man1="$work/prefix/share/man/man1"
commands=$("$work/prefix/bin/tackle" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && NF {print $1}')
[ "$(echo "$commands" | wc -w)" -ge 8 ] || { echo "tackle --help lists only: $commands"; exit 1; }
for page in tackle $(for c in $commands; do echo "tackle-$c"; done); do
  [ -f "$man1/$page.1" ] || { echo "no man page $man1/$page.1"; exit 1; }
  warnings=$(groff -man -Tutf8 -ww -z "$man1/$page.1" 2>&1)
  [ -z "$warnings" ] || { echo "groff warns on $page.1: $warnings"; exit 1; }
  groff -man -Tutf8 -P-cbou "$man1/$page.1" 2>/dev/null | grep -q "^NAME$" || { echo "$page.1 renders without a NAME section"; exit 1; }
done
groff -man -Tutf8 -P-cbou "$man1/tackle-check.1" 2>/dev/null | grep -q -- "--results-format" || { echo "tackle-check.1 lacks --results-format"; exit 1; }
# The documentation and the examples: every page of docs/, the benchmarks' results, every
# example (the PrairieLearn question's problem.yaml still reaches its example).
doc="$work/prefix/share/doc/tackle"
for page in "$source"/docs/*.md; do
  cmp -s "$page" "$doc/$(basename "$page")" || { echo "not installed: docs/$(basename "$page")"; exit 1; }
done
[ -f "$doc/bench/RESULTS.md" ] || { echo "not installed: bench/RESULTS.md"; exit 1; }
for sketch in "$source"/docs/cookbook/*.svg; do
  [ -f "$doc/cookbook/$(basename "$sketch")" ] || { echo "not installed: docs/cookbook/$(basename "$sketch")"; exit 1; }
done
for example in "$source"/examples/*.yaml; do
  [ -f "$doc/examples/$(basename "$example")" ] || { echo "not installed: examples/$(basename "$example")"; exit 1; }
done
"$work/prefix/bin/tackle" solve "$doc/examples/prairielearn/pulley-tension/problem.yaml" | grep -q "^T = 2\*F\*m_B/(9\*m_A + 4\*m_B)  = 20 N$"
[ -x "$doc/examples/gradescope/pulley-tension/run_autograder" ] || { echo "the Gradescope example's run_autograder is not executable"; exit 1; }
# The bash completion (it completes the commands), the license.
completed=$(bash -c "source '$work/prefix/share/bash-completion/completions/tackle'; COMP_WORDS=(tackle che); COMP_CWORD=1; _tackle; echo \${COMPREPLY[*]}")
[ "$completed" = "check" ]
grep -q "GNU GENERAL PUBLIC LICENSE" "$work/prefix/share/doc/tackle/LICENSE"
# The install can move: the rules are found from the executable.
mv "$work/prefix" "$work/moved"
"$work/moved/bin/tackle" --version | grep -q "(rules: $work/moved/share/tackle/rules)$"
mv "$work/moved" "$work/prefix"
cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" 2>&1 || { tail -30 "$work/build.log"; exit 1; }
"$work/consumer/consumer" "$source/examples/atwood-machine.yaml" | grep -q "^T = 2\*g\*m_A\*m_B/(m_A + m_B)$"
# The Python module, when it was built: importable from the prefix, the rules found beside it.
if ls "$work/prefix"/lib/python3/dist-packages/tackle*.so > /dev/null 2>&1; then
  PYTHONPATH="$work/prefix/lib/python3/dist-packages" python3 -c "import tackle; print(tackle.rules_dir())" |
    grep -q "^$work/prefix/share/tackle/rules$"
  PYTHONPATH="$work/prefix/lib/python3/dist-packages" python3 -c "
import tackle
p = tackle.Problem('$source/examples/atwood-machine.yaml')
assert [a['closed_form'] for a in p.answers() if a['name'] == 'T'] == ['2*g*m_A*m_B/(m_A + m_B)']"
fi
echo "installed, moved, and built against: ok"
