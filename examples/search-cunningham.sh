#!/usr/bin/env bash
# Cunningham chain searches from scratch, in one pipeline each:
#   first kind  (cc1): k*2^n-1, k*2^(n+1)-1, ...  (each member is 2p+1 of the one before)
#   second kind (cc2): k*2^n+1, k*2^(n+1)+1, ...  (each member is 2p-1 of the one before)
#
#   sieve cc1|cc2 --length L  removes every k with a member that has a prime
#                             factor up to PMAX;
#   mrtest                    runs BPSW on the survivors, keeps probable chains;
#   riesel                    proves every member: Lucas-Lehmer-Riesel for
#                             k*2^m-1, Proth for k*2^m+1.
#
# Run as is it makes five searches, each expected to find a chain or more:
#   length 2 at n = 2000 (chains of about 600 digits), k <= 10^6:
#     about 1.3 chains of each kind on average;
#   length 3 at n = 700 (about 220 digits), k <= 5*10^7: about 2.2 of each;
#   the "Prime Hunting" paper's own Cc22 parametrisation, k = h0 + c*x with
#     h0 = 0 and c = 30030 = 2*3*5*7*11*13 (no member has a factor below 17),
#     second kind, length 2, at n = 2000 for x <= 10^5 (k up to 3*10^9, all
#     even): 2,094 survivors and about 1.4 chains expected (the project ran
#     n = 256000; PAPER_N and PAPER_XMAX change it).
# (A chain of L members is prime with probability about C_L*2^L/ln(N)^L,
# with C_2 = 0.66 and C_3 = 0.71 from the local densities of the primes.)
# riesel writes each member with k made odd: 353364*2^2000-1 appears as
# 88341*2^2002-1, and the paper's 30030x*2^2000+1 as
# (30030x/2^t)*2^(2000+t)+1 (x = 94728 gives 177792615*2^2004+1).
# Measured on the 2-core development machine: 4 s for each of the first
# four searches, 16 s in all (up to 45 s while other jobs shared it); the
# paper's, whose 2,100 survivors of 600 digits each get BPSW, 14 to 17 s
# more while other jobs shared it.
#
# mrtest --trial-bound 0: the sieve has already divided by every prime up
# to PMAX, so mrtest's own trial division would be wasted time.
#
# Other sizes: LEN2_N, LEN2_KMAX, LEN3_N, LEN3_KMAX, PMAX. Longer chains
# take --length up to 64 (sieve) but become rare fast: every extra member
# divides the expectation by about ln(N)/2. Production-sized searches run
# in pieces: sieve-cron.sh or the shard examples for the sieve,
# riesel-cron.sh for the proofs.
set -euo pipefail
export LC_ALL=C
len2_n="${LEN2_N:-2000}"
len2_kmax="${LEN2_KMAX:-1e6}"
len3_n="${LEN3_N:-700}"
len3_kmax="${LEN3_KMAX:-5e7}"
paper_n="${PAPER_N:-2000}"
paper_xmax="${PAPER_XMAX:-1e5}"
pmax="${PMAX:-1e9}"
threads="${THREADS:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

searches=0
elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }

# search KIND LENGTH N K-OPTIONS...: one sieve | mrtest | riesel pipeline,
# for the k of --k 1:KMAX or of --h0 H --c C --x 1:XMAX.
search() {
  local kind="$1" length="$2" n="$3"
  shift 3
  searches=$((searches + 1))
  local out="$work/search$searches.jsonl" state="$work/search$searches.state" start proved sign=-
  if [[ "$kind" == cc2 ]]; then sign=+; fi
  echo "== $kind, length $length: k*2^($n+i)${sign}1, i = 0..$((length - 1)), for $*, sieved to $pmax"
  start="$EPOCHREALTIME"
  sieve "$kind" --length "$length" --n "$n" "$@" --pmax "$pmax" -j "$threads" -q \
    | tee "$work/survivors.jsonl" \
    | mrtest -j "$threads" --trial-bound 0 --keep prime,probable \
    | riesel -j "$threads" -q --state "$state" > "$out"
  # The record's own verdict (its members' come after "seconds").
  proved=$(grep -c '"verdict":"prime","test":"[a-z]*","seconds"' "$out" || true)
  echo "   $(wc -l < "$work/survivors.jsonl") survivors of the sieve, $proved chain(s) proved; $(elapsed "$start") s"
  # Every member proved, LLR-style, with its proof time (k made odd).
  sed 's/^/   /' "$state/lresults.txt"
}

search cc1 2 "$len2_n" --k "1:$len2_kmax"
search cc2 2 "$len2_n" --k "1:$len2_kmax"
search cc1 3 "$len3_n" --k "1:$len3_kmax"
search cc2 3 "$len3_n" --k "1:$len3_kmax"
search cc2 2 "$paper_n" --h0 0 --c 30030 --x "1:$paper_xmax"
