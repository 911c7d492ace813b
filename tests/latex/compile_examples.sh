#!/usr/bin/env bash
# Derives every example as LaTeX and compiles it with pdflatex; fails on the first error, and on
# any line that runs past the margin by more than 10 pt (an Overfull \hbox: cut off in print).
set -euo pipefail
tackle=$1
examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
count=0
# Lines past the margin by more than 10 pt, in a pdflatex log.
overfull() {
  grep -o 'Overfull \\hbox ([0-9.]*pt' "$1" | grep -o '[0-9.]*' | awk '$1 > 10' | wc -l
}
# Words printed past the text block's left or right edge by more than 10 pt (2.5 cm margins),
# from pdftotext's word boxes: what no Overfull warning reports, such as an equation's tag too
# wide to sit beside it, which amsmath puts below the equation and out into the margin.
past_margins() {
  pdftotext -bbox "$1" - | awk -v margin=70.87 '
    /<page / { match($0, /width="[0-9.]+"/); w = substr($0, RSTART + 7, RLENGTH - 8) + 0 }
    /<word / {
      match($0, /xMin="[0-9.]+"/); x0 = substr($0, RSTART + 6, RLENGTH - 7) + 0
      match($0, /xMax="[0-9.]+"/); x1 = substr($0, RSTART + 6, RLENGTH - 7) + 0
      if (x0 < margin - 10 || x1 > w - margin + 10) { n++; sub(/.*">/, ""); sub(/<.*/, ""); print "  past the margin: " $0 > "/dev/stderr" }
    }
    END { print n + 0 }'
}
for f in "$examples"/*.yaml; do
  name=$(basename "$f" .yaml)
  "$tackle" derive "$f" --format latex -o "$work/$name.tex"
  if ! (cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error "$name.tex" >"$name.out" 2>&1); then
    echo "pdflatex failed for $f:"; tail -30 "$work/$name.out"; exit 1
  fi
  # Vector fonts only (lmodern): a Type 3 font is a bitmap that prints and zooms badly.
  if command -v pdffonts > /dev/null && pdffonts "$work/$name.pdf" | grep -q "Type 3"; then
    echo "bitmap (Type 3) fonts in the derivation of $f:"; pdffonts "$work/$name.pdf"; exit 1
  fi
  if [ "$(overfull "$work/$name.log")" -gt 0 ]; then
    echo "lines past the margin by more than 10 pt in the derivation of $f:"; grep -A3 'Overfull' "$work/$name.log"; exit 1
  fi
  if command -v pdftotext > /dev/null && [ "$(past_margins "$work/$name.pdf")" -gt 0 ]; then
    echo "words past the margin in the derivation of $f (above)"; exit 1
  fi
  "$tackle" solve "$f" --format latex -o "$work/$name-key.tex"
  (cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error "$name-key.tex" >"$name-key.out" 2>&1) \
    || { echo "pdflatex failed for the answers of $f"; tail -30 "$work/$name-key.out"; exit 1; }
  count=$((count + 1))
done
# The answer key of every example, with variants.
"$tackle" key "$examples"/*.yaml --format latex --variants 3 --seed 1 -o "$work/key.tex"
(cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error key.tex >key.out 2>&1) \
  || { echo "pdflatex failed for the answer key"; tail -30 "$work/key.out"; exit 1; }
[ "$(overfull "$work/key.log")" -eq 0 ] || { echo "lines past the margin in the answer key:"; grep -A3 'Overfull' "$work/key.log"; exit 1; }
# The problem sheets of every example, with the same variants.
"$tackle" sheet "$examples"/*.yaml --format latex --variants 2 --seed 1 --figures -o "$work/sheet.tex"
(cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error sheet.tex >sheet.out 2>&1) \
  || { echo "pdflatex failed for the problem sheets"; tail -30 "$work/sheet.out"; exit 1; }
[ "$(overfull "$work/sheet.log")" -eq 0 ] || { echo "lines past the margin in the sheets:"; grep -A3 'Overfull' "$work/sheet.log"; exit 1; }
echo "compiled $count examples, their answer key and their sheets"
[ "$count" -gt 0 ]
