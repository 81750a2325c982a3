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
