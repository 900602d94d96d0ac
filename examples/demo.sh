#!/usr/bin/env bash
# The toolkit's main job, end to end. `make demo` builds and runs this.
# For now: mrtest on real numbers from the prime-hunting literature.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

echo "== The 'Prime Hunting' paper (Farkas et al.): 778965587811*2^36627-1 is prime,"
echo "   778965587811*2^36629-1 is not (BPSW with the k*2^n-1 special-form reduction):"
printf '778965587811*2^36627-1\n778965587811*2^36629-1\n' | mrtest -j 2

echo
echo "== Mersenne exponents below 1300, found by testing every 2^p-1:"
seq 2 1300 | sed 's/^/2^/; s/$/-1/' | mrtest -j 2 --keep prime,probable --csv | cut -d, -f3 | tail -n +2 | tr '\n' ' '
echo

echo
echo "== A pipeline: candidates k*2^n+1 from a NewPGen-style sieve file, survivors kept:"
bash "$here/mrtest-newpgen.sh"
