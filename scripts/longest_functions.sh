#!/usr/bin/env bash
# The longest functions (and lambdas' enclosing functions) of a folder, by
# lines from signature to closing brace, as Universal Ctags sees them (its
# `end` field): the figure the structure reviews quote.
# Usage: scripts/longest_functions.sh FOLDER [COUNT]
set -euo pipefail
folder=${1:?usage: scripts/longest_functions.sh FOLDER [COUNT]}
count=${2:-10}
ctags -x --c++-kinds=f --fields=+e --_xformat='%{end} %{line} %{input} %{name}' -R \
  --languages=C++ "$folder" |
  awk '$1 != "-" { printf "%5d %s:%d %s\n", $1 - $2 + 1, $3, $2, $4 }' |
  sort -rn | head -n "$count"
