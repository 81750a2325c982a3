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
# Screenshots of the app need a display (e.g. `Xvfb :99 &` and DISPLAY=:99). Their status line
# shows timings, so tests/docs_figures.rs does not compare them.
if [[ -n "${DISPLAY:-}" ]]; then
  rm -f docs/figures/app-zh.png
  ./target/release/barylab --fresh --lang zh --window 1280x800 --pin 400,420 \
    --screenshot docs/figures/app-zh.png
  echo "docs/figures/app-zh.png"
fi
