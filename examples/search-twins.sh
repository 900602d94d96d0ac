#!/usr/bin/env bash
# A twin prime search from scratch, k*2^n-1 and k*2^n+1 both prime, in one
# pipeline:
#
#   sieve twin  removes every k for which k*2^n-1 or k*2^n+1 has a prime
#               factor up to PMAX;
#   mrtest      runs BPSW on the survivors and keeps the probable twins;
#   riesel      proves both members: Lucas-Lehmer-Riesel for k*2^n-1,
#               Proth for k*2^n+1.
#
# Run as is it searches n = 3300, k <= 2*10^6: twins of about 1,000 digits.
# A pair k*2^n+-1 is a twin with probability about 4*C2/ln(N)^2 (C2 =
# 0.6602, Hardy-Littlewood), 5e-7 here, so the range holds about 1 twin
# on average; this one holds one, 440682*2^3300+-1 (riesel writes it as
# 220341*2^3301+-1, k made odd). Measured on the 2-core development
# machine: 16 s in all (up to a minute while other jobs shared it). The
# sieve leaves 3,813 candidates in about 2 s; nearly all of the rest is
# mrtest, which stops at the first composite member of each pair; the two
# proofs take 0.02 s.
#
# mrtest --trial-bound 0: the sieve has already divided by every prime up
# to PMAX, so mrtest's own trial division (to 1.4 million at this size)
# would only double its time.
#
# Other ranges: KMIN=2000001 KMAX=4e6 bash search-twins.sh (another twin
# expected on average). Production sizes: the seed's twin
# 16869987339975*2^171960+-1 (51,779 digits) came from a search at
# n = 171960 with k of about 1.7*10^13. At that size each proof takes one
# to two minutes here (riesel(1), PERFORMANCE), BPSW as long, and the
# sieve should go to 10^12 or further (sieve --min-rate says when to
# stop), so the work runs in pieces: sieve-cron.sh,
# sieve-shards-parallel.sh or sieve-slurm-array.sh for the sieve,
# riesel-cron.sh for the proofs.
set -euo pipefail
export LC_ALL=C
n="${N:-3300}"
kmin="${KMIN:-1}"
kmax="${KMAX:-2e6}"
pmax="${PMAX:-1e9}"
threads="${THREADS:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }

echo "twin candidates k*2^$n-1, k*2^$n+1 for k = $kmin..$kmax, sieved with the primes up to $pmax"
start="$EPOCHREALTIME"
sieve twin --n "$n" --k "$kmin:$kmax" --pmax "$pmax" -j "$threads" -q \
  | tee "$work/survivors.jsonl" \
  | mrtest -j "$threads" --trial-bound 0 --keep prime,probable \
  | riesel -j "$threads" -q --state "$work/riesel" > "$work/twins.jsonl"
echo "  $(wc -l < "$work/survivors.jsonl") survivors of the sieve, $(wc -l < "$work/twins.jsonl") passed BPSW; $(elapsed "$start") s in all"

# The proved twins: riesel's records, then LLR-style lines with each proof's time.
proved=$(grep -c '"form":"twin","verdict":"prime"' "$work/twins.jsonl" || true)
echo "twin primes proved: $proved"
sed 's/^/  /' "$work/twins.jsonl"
sed 's/^/  /' "$work/riesel/lresults.txt"
