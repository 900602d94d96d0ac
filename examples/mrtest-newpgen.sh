#!/usr/bin/env bash
# mrtest inside a pipeline: test the candidates of a NewPGen file (k*2^n+1,
# n fixed) on two cores, keep the (probable) primes, and count them per
# verdict. The file is made here; sieve output has the same shape.
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

{
  echo "1000000:P:1:2:1"                                       # k*2^n+1, sieved to 10^6
  for k in $(seq 1 2 2001); do echo "$k 1279"; done
} > "$work/candidates.npg"

mrtest -j 2 --keep prime,probable "$work/candidates.npg" > "$work/primes.jsonl"
echo "$(wc -l < "$work/primes.jsonl") probable primes k*2^1279+1 with k < 2002:"
cut -d, -f1 "$work/primes.jsonl" | sed 's/{"k"://' | tr '\n' ' '
echo

# Theorem 2.3 of "Prime Hunting" (Miller-Rabin with every base below
# 2(ln N)^2, a proof if the Generalised Riemann Hypothesis holds), on
# numbers of 30 digits: about 8,900 bases each, a few ms per prime. For
# k*2^n+-1 of real size use riesel instead (mrtest(1), COST OF MR-GRH).
for i in $(seq -w 1 2 999); do echo "100000000000000000000000000$i"; done |
  mrtest -j 2 -t mr-grh --keep prime-if-grh | sed 's/{"number":"\([0-9]*\)".*/\1/' | tr '\n' ' '
echo
