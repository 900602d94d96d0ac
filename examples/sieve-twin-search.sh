#!/usr/bin/env bash
# A twin prime search k*2^n-1, k*2^n+1 in two steps: sieve removes the
# candidates with a small factor, mrtest tests the survivors.
#
# Run as is it takes a second (n = 500, k <= 10^5, primes to 10^7). The
# production sizes of the "Prime Hunting" search, each a long run (see
# sieve-cron.sh and the shard examples for running them):
#   N=171960 KMAX=1e9 PMAX=1e12 bash sieve-twin-search.sh   # pmax: until --min-rate says stop
# and with the seed's parametrisation k = h0 + c*x (c a primorial):
#   sieve twin --n 171960 --h0 3 --c 30030 --x 1:1e9 --pmax 1e12 --newpgen
# At n = 171960 each test takes minutes; give the NewPGen file to LLR or
# PFGW instead of mrtest (both read it: `llr64 twin.npg`, `pfgw64 twin.npg`).
set -euo pipefail
n="${N:-500}"
kmax="${KMAX:-1e5}"
pmax="${PMAX:-1e7}"
threads="${THREADS:-2}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# 1. Sieve. NewPGen output; --factors keeps the proof of every removal.
sieve twin --n "$n" --k "1:$kmax" --pmax "$pmax" -j "$threads" \
  --newpgen --factors "$work/factors.txt" > "$work/twin.npg"

candidates=$(( $(wc -l < "$work/factors.txt") + $(wc -l < "$work/twin.npg") - 1 ))
survivors=$(( $(wc -l < "$work/twin.npg") - 1 ))
echo "twin candidates k*2^$n+-1, k <= $kmax: $candidates"
echo "survivors of the sieve to $pmax: $survivors (header: $(head -1 "$work/twin.npg"))"
echo "first removals:"
head -3 "$work/factors.txt" | sed 's/^/  /'

# 2. Test the survivors; keep the twins whose both members are (probable) primes.
mrtest -j "$threads" --keep prime,probable "$work/twin.npg" > "$work/twins.jsonl"
echo "twin primes found: $(wc -l < "$work/twins.jsonl")"
sed 's/,"verdict".*//; s/^{//; s/^/  /' "$work/twins.jsonl"
