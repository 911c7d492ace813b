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
# The man page, the bash completion (it completes the commands), the license.
man -l "$work/prefix/share/man/man1/tackle.1" > /dev/null 2>&1 || groff -man -Tutf8 -ww "$work/prefix/share/man/man1/tackle.1" > /dev/null
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
