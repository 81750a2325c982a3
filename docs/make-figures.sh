#!/usr/bin/env bash
# Renders every figure listed in docs/figures/list.txt with the barylab CLI: `barylab render`,
# or `barylab figure` for lines whose arguments start with the word `figure`.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
grep -v '^#' docs/figures/list.txt | grep -v '^\s*$' | while read -r out args; do
  command=render
  if [[ "$args" == figure\ * ]]; then
    command=figure
    args=${args#figure }
  fi
  # shellcheck disable=SC2086
  ./target/release/barylab "$command" $args -o "docs/figures/$out" >/dev/null
  echo "docs/figures/$out"
done
# The animations of docs/animation.md (`barylab animate`; the same flags as their captions say).
anim() { out=$1; shift; rm -f "docs/figures/$out"; ./target/release/barylab animate "$@" -o "docs/figures/$out" >/dev/null; echo "docs/figures/$out"; }
anim animate-depth.gif assets/scenes/default.json --size 240x180 --sweep depth --frames 16 --fps 8
anim animate-wipe.apng assets/scenes/default.json --size 240x180 --sweep affine-perspective --frames 12 --fps 6
for kind in scanline edge; do
  anim "animate-fill-$kind.gif" assets/scenes/default.json --size 24x18 --pixel-size 10 --no-handles \
    --sweep "fill-$kind" --frames 25 --fps 8
done
# Screenshots of the app need a display (e.g. `Xvfb :99 &` and DISPLAY=:99). Their status line
# shows timings, so tests/docs_figures.rs does not compare them.
if [[ -n "${DISPLAY:-}" ]]; then
  rm -f docs/figures/app-zh.png
  ./target/release/barylab --fresh --lang zh --window 1280x800 --pin 400,420 \
    --screenshot docs/figures/app-zh.png
  echo "docs/figures/app-zh.png"
fi
