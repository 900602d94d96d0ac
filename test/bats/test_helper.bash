# Shared set-up for the bats suites: bats-support/bats-assert from Debian's
# packages, the freshly built tools first on PATH, a scratch directory.
load '/usr/lib/bats/bats-support/load'
load '/usr/lib/bats/bats-assert/load'

TOOLKIT_ROOT="${TOOLKIT_ROOT:-$(cd "$BATS_TEST_DIRNAME/../.." && pwd)}"
TOOLKIT_BIN="${TOOLKIT_BIN:-$TOOLKIT_ROOT/build}"
TOOLKIT_BUILD="${TOOLKIT_BUILD:-$TOOLKIT_BIN}"
PATH="$TOOLKIT_BIN:$PATH"
FIXTURES="$TOOLKIT_ROOT/test/fixtures"

# json-field FIELD < records: one value per line (test/bin, plain python3).
PATH="$TOOLKIT_ROOT/test/bin:$PATH"
