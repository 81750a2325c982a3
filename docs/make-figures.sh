#!/usr/bin/env bash
# Renders every figure listed in docs/figures/list.txt with the barylab CLI.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
grep -v '^#' docs/figures/list.txt | grep -v '^\s*$' | while read -r out args; do
  # shellcheck disable=SC2086
  ./target/release/barylab render $args -o "docs/figures/$out" >/dev/null
  echo "docs/figures/$out"
done
