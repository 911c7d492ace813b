#!/usr/bin/env bash
# Determinism under any memory layout: every command and format of every example (and of
# every bad description) is run in many separate processes, with address randomisation on
# (GiNaC's hash order follows the addresses, so it changes from run to run) and under
# `setarch -R` with environments of different sizes (which move the stack); so is a batch of
# answer checks. Each command must give one distinct output (stdout, stderr and exit code)
# over all its runs.
# Usage: run.sh TACKLE_BINARY SOURCE_DIR [RUNS]   (RUNS: ASLR processes per command, default 20)
set -uo pipefail
tackle=$1
src=$2
runs=${3:-${TACKLE_DETERMINISM_RUNS:-20}}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

commands=()
for f in "$src"/examples/*.yaml; do
  for fmt in text latex markdown json html; do commands+=("derive $f --format $fmt"); done
  commands+=("isolate $f --all" "isolate $f --all --format json")
done
commands+=("key $src/examples/*.yaml --variants 3 --seed 11 --format json")
commands+=("key $src/examples/*.yaml --variants 2 --seed 5 --format latex")
commands+=("sheet $src/examples/*.yaml --variants 2 --seed 5 --format html --figures")
for f in "$src"/tests/data/bad/*.yaml; do commands+=("derive $f"); done
# The fuzzers' regressions: descriptions whose closed forms carry signs that two sums could
# take (two of them printed a different form in about every third run before the printer
# chose by text).
for f in "$src"/tests/fuzz/regressions/description/*; do
  commands+=("derive $f --format text" "derive $f --format latex" "solve $f --format json")
done
# The cross-check's regressions: motions that turn against an assumed direction, whose extreme
# over time took the sign of a square's base and whose first stop took the last bits of a sum
# from GiNaC's order (each varied in about every third run before).
for f in "$src"/tests/crosscheck/regressions/*.yaml; do
  commands+=("derive $f --format text" "derive $f --format json")
done
# Answer checks whose feedback could follow the order of a sum's terms (mixed dimensions,
# the diagnoses of wrong answers).
commands+=("check $src/examples/sample-12.8-sign-board.yaml --batch $src/tests/determinism/sign-board-answers.jsonl")
commands+=("check $src/examples/sample-12.7-suitcase.yaml --batch $src/tests/determinism/suitcase-answers.jsonl")

pad() { head -c "$1" /dev/zero | tr '\0' x; }
arch=$(uname -m)
layouts=()
setarch "$arch" -R true 2>/dev/null && layouts=(0 1000 5000 20000)

one() {  # one() OUTFILE ARGS... : the hash of stdout, stderr and exit code
  local out=$1; shift
  { "$@" 2>&1; echo "exit $?"; } | sha256sum | cut -d' ' -f1 >>"$out"
}

failed=0
n=0
for c in "${commands[@]}"; do
  n=$((n + 1))
  h="$work/$n"
  : >"$h"
  # shellcheck disable=SC2086
  for ((i = 0; i < runs; i++)); do one "$h" $tackle $c; done
  for p in "${layouts[@]}"; do
    # shellcheck disable=SC2086
    one "$h" env "TACKLE_PAD=$(pad "$p")" setarch "$arch" -R $tackle $c
  done
  distinct=$(sort -u "$h" | wc -l)
  if [ "$distinct" -ne 1 ]; then
    echo "NOT DETERMINISTIC ($distinct distinct outputs in $(wc -l <"$h") runs): tackle $c"
    failed=$((failed + 1))
  fi
done
total=$(( ${#commands[@]} * (runs + ${#layouts[@]}) ))
echo "determinism: ${#commands[@]} commands, $total processes ($runs with ASLR and ${#layouts[@]} under setarch -R each): $failed not deterministic"
[ "$failed" -eq 0 ]
