#!/usr/bin/env bash
# Every example's HTML report (derive), one answers page (solve), the problem sheets with
# their figures and the answer key with its variants, opened in headless Chromium: every formula typeset by KaTeX, no KaTeX error,
# and nothing fetched from the network (the pages are self-contained).
set -euo pipefail
tackle=$1
examples=$2
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is not installed (scripts/setup installs it)"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pages=()
for f in "$examples"/*.yaml; do
  name=$(basename "$f" .yaml)
  "$tackle" derive "$f" --format html -o "$work/$name.html"
  pages+=("$work/$name.html")
done
"$tackle" solve "$examples/sample-12.8-sign-board.yaml" --format html -o "$work/solve.html"
"$tackle" sheet "$examples"/*.yaml --format html --variants 2 --seed 1 --figures -o "$work/sheet.html"
"$tackle" key "$examples"/*.yaml --format html --variants 2 --seed 1 -o "$work/key.html"
pages+=("$work/solve.html" "$work/sheet.html" "$work/key.html")
occurrences() { { grep -o "$1" "$2" || true; } | wc -l; }
count=0
for page in "${pages[@]}"; do
  # Self-contained: no script, style, image or font from anywhere else.
  if grep -Eq '(src|href)="(https?:)?//|url\((https?:)?//' "$page"; then
    echo "$page refers to the network:"; grep -Eo '(src|href)="(https?:)?//[^"]*|url\((https?:)?//[^)]*' "$page" | head; exit 1
  fi
  expected=$(occurrences 'class="math' "$page")
  # Measured in a copy: after the typesetting, every equation, paragraph and figure must fit
  # its column in a 1000 px window (the count of those wider, and the worst, in pixels).
  measured="${page%.html}-measured.html"
  sed 's|</body>|<script>(function m(){if(document.body.getAttribute("data-math-rendered")!=="true"){setTimeout(m,20);return;}let n=0,w=0,what="";for(const e of document.querySelectorAll(".eq, p, li, figure")){const o=e.scrollWidth-e.clientWidth;if(o>2){n++;if(o>w){w=o;what=e.textContent.slice(0,80);}}}document.body.setAttribute("data-overflow",n+" "+w+" "+what.replace(/[^ -~]/g,"?"));})();</script></body>|' "$page" > "$measured"
  timeout 60 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --virtual-time-budget=10000 --window-size=1000,800 \
    --dump-dom "file://$measured" > "$work/dom.html" 2> "$work/browser.err" || { echo "chromium failed on $page"; tail "$work/browser.err"; exit 1; }
  overflow=$(grep -o 'data-overflow="[^"]*"' "$work/dom.html" | head -1)
  case "$overflow" in
    'data-overflow="0 '*) ;;
    '') echo "$page: the width was not measured"; exit 1 ;;
    *) echo "$page: wider than its column in a 1000 px window (count, worst in px, the first words): $overflow"; exit 1 ;;
  esac
  grep -q 'data-math-rendered="true"' "$work/dom.html" || { echo "$page: the typesetting script did not run"; exit 1; }
  errors=$(occurrences 'class="katex-error"' "$work/dom.html")
  if [ "$errors" -ne 0 ]; then
    echo "$page: $errors KaTeX errors:"; grep -o '<span class="katex-error"[^>]*>' "$work/dom.html" | head -5; exit 1
  fi
  typeset=$(occurrences 'class="katex"' "$work/dom.html")
  if [ "$typeset" -ne "$expected" ]; then
    echo "$page: $typeset of $expected formulas typeset"; exit 1
  fi
  count=$((count + 1))
done
echo "rendered $count pages in $browser with every formula typeset"
[ "$count" -gt 2 ]
