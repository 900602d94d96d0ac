#!/usr/bin/env bash
# The C++ sources as .clang-format lays them out: `format.sh` rewrites them
# in place (`make format`), `format.sh --check` lists the files that differ
# and fails (the source_format test). One clang-format for everyone:
# Debian's (clang-format-14 on bookworm); another version may lay out a
# few lines differently.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(find libshared tools test/unit bench fuzz -name '*.cpp' -o -name '*.hpp' | sort)
if [ "${1:-}" = --check ]; then
  clang-format --dry-run --Werror "${files[@]}"
else
  clang-format -i "${files[@]}"
fi
