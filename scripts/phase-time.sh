#!/usr/bin/env bash
# phase-time.sh COMMAND...: runs COMMAND, then prints how long it took on
# stderr ("phase 123 s: COMMAND"), keeping its exit status: each phase of
# `make test` and `make demo` reports its wall-clock time in the log.
start=$(date +%s)
status=0
"$@" || status=$?
echo "phase $(( $(date +%s) - start )) s: $*" >&2
exit "$status"
