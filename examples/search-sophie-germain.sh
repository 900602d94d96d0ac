#!/usr/bin/env bash
# A Sophie Germain prime search from scratch: p = k*2^n-1 with 2p+1 =
# k*2^(n+1)-1 also prime, in one pipeline:
#
#   sieve sg    removes every k for which p or 2p+1 has a prime factor up
#               to PMAX;
#   mrtest      runs BPSW on the survivors and keeps the probable pairs;
#   riesel      proves both members with Lucas-Lehmer-Riesel.
#
# Run as is it searches n = 3300, k <= 3*10^6: primes p of about 1,000
# digits. Like a twin pair, a pair (p, 2p+1) of this shape is prime with
# probability about 4*C2/ln(p)^2 (C2 = 0.6602), so the range holds about
# 1.5 on average; it holds one, k = 2898447 (none with k <= 2*10^6).
# Measured on the 2-core development machine: 22 s in all (up to a minute
# while other jobs shared it); 5,760 candidates survive the sieve, mrtest
# takes nearly all of the time, the two proofs 0.02 s.
#
# mrtest --trial-bound 0: the sieve has already divided by every prime up
# to PMAX; mrtest's own trial division would double its time.
#
# Production sizes: n in the hundred thousands, k up to 10^9 or more (or
# k = h0 + c*x with a primorial c, sieve --h0 --c --x, as in "Prime
# Hunting"), sieved to 10^12 or further. Each proof then takes a minute or
# more here, so the work runs in pieces: sieve-cron.sh or the shard
# examples for the sieve, riesel-cron.sh for the proofs. The same three
# steps with files in between:
#   sieve sg --n 171960 --h0 9 --c 30030 --x 1:1e9 --pmax 1e12 -j 2 --newpgen > sg.npg
#   mrtest -j 2 --trial-bound 0 --keep prime,probable sg.npg > sg-prp.jsonl
#   riesel -j 2 --state sg-state sg-prp.jsonl > sg-proved.jsonl
set -euo pipefail
export LC_ALL=C
n="${N:-3300}"
kmin="${KMIN:-1}"
kmax="${KMAX:-3e6}"
pmax="${PMAX:-1e9}"
threads="${THREADS:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }

echo "Sophie Germain candidates k*2^$n-1, k*2^$((n + 1))-1 for k = $kmin..$kmax, sieved with the primes up to $pmax"
start="$EPOCHREALTIME"
sieve sg --n "$n" --k "$kmin:$kmax" --pmax "$pmax" -j "$threads" -q \
  | tee "$work/survivors.jsonl" \
  | mrtest -j "$threads" --trial-bound 0 --keep prime,probable \
  | riesel -j "$threads" -q --state "$work/riesel" > "$work/sg.jsonl"
echo "  $(wc -l < "$work/survivors.jsonl") survivors of the sieve, $(wc -l < "$work/sg.jsonl") passed BPSW; $(elapsed "$start") s in all"

# The proved pairs: riesel's records, then LLR-style lines with each proof's time.
proved=$(grep -c '"form":"sg","verdict":"prime"' "$work/sg.jsonl" || true)
echo "Sophie Germain primes proved: $proved"
sed 's/^/  /' "$work/sg.jsonl"
sed 's/^/  /' "$work/riesel/lresults.txt"
