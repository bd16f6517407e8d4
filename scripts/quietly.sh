#!/usr/bin/env bash
# Runs a command with its output in a log file instead of the terminal: one
# line says what runs and where its log is; if the command fails, the log's
# last lines are shown and the exit status is passed on.
#   scripts/quietly.sh LOG LABEL COMMAND [ARGS...]
# `make demo` builds through it, so the terminal shows the build only when it
# fails (the whole output stays in LOG). A command that succeeds without any
# output is not announced.
set -uo pipefail
log=${1:?usage: scripts/quietly.sh LOG LABEL COMMAND [ARGS...]}
label=${2:?usage: scripts/quietly.sh LOG LABEL COMMAND [ARGS...]}
shift 2
mkdir -p "$(dirname "$log")"
start=$SECONDS
"$@" > "$log" 2>&1
status=$?
if [ $status -ne 0 ]; then
  echo "$label failed (exit $status); the last lines of $log:" >&2
  tail -n 30 "$log" >&2
  echo "$label failed: the whole output is in $log" >&2
  exit $status
fi
# A command that printed nothing (the dependencies all there) says nothing.
[ -s "$log" ] || exit 0
echo "$label: done in $((SECONDS - start)) s (log: $log)"
