#!/usr/bin/env bash
# One sieve split into shards that run at the same time, here with GNU
# parallel on this machine or on several machines over ssh, and merged into
# exactly the file one run writes.
#
# --shard K/N: every shard sieves the primes up to 2^20 itself (a few
# seconds at most) and then every N-th block of 2^22 larger primes, the
# K-th of them. Shards share nothing, so they can run anywhere; `sieve
# merge` keeps the candidates that survived in every shard.
#
# Run as is it takes a few seconds (n = 1000, k <= 10^6, primes to 10^9,
# 4 shards on this machine's cores). Production size, say 64 shards over
# the machines of a lab (sieve must be on each host's PATH; GNU parallel
# logs in with ssh and brings every shard's output back here):
#   HOSTS=8/host1,8/host2,8/host3,8/host4 SHARDS=64 \
#     N=171960 KMIN=1 KMAX=1e9 PMAX=1e12 CHECK=no bash sieve-shards-parallel.sh
# (8/host1 runs 8 shards at a time on host1). CHECK=no skips the single
# run that proves the merge, which at that size takes as long as all the
# shards on one core. HOSTS=2/: takes the ssh code path on this machine
# alone (":" is parallel's name for the local host).
set -euo pipefail
n="${N:-1000}"
kmin="${KMIN:-1}"
kmax="${KMAX:-1e6}"
pmax="${PMAX:-1e9}"
shards="${SHARDS:-4}"
hosts="${HOSTS:-}"          # empty: this machine only
check="${CHECK:-yes}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Local: one shard per core at a time. Remote: -S names the hosts.
# --results FILE{} stores each shard's standard output in a local file,
# wherever the shard ran; --halt stops everything when one shard fails.
where=()
if [[ -n "$hosts" ]]; then where=(-S "$hosts"); fi
seq 1 "$shards" | parallel "${where[@]}" --halt now,fail=1 \
  --results "$work/shard{}.npg" \
  sieve twin --n "$n" --k "$kmin:$kmax" --pmax "$pmax" --newpgen -q --shard "{}/$shards"
# The same for a literal list of shards: parallel ... --shard {}/4 ::: 1 2 3 4

shard_files=()
for k in $(seq 1 "$shards"); do shard_files+=("$work/shard$k.npg"); done
sieve merge "${shard_files[@]}" > "$work/twin.npg"
echo "$shards shards of twin k*2^$n+-1, k in $kmin..$kmax, primes to $pmax:"
for file in "${shard_files[@]}"; do
  echo "  $(basename "$file"): $(( $(wc -l < "$file") - 2 )) candidates left"  # header and shard line
done
echo "merged: $(( $(wc -l < "$work/twin.npg") - 1 )) candidates, header $(head -1 "$work/twin.npg")"

if [[ "$check" == yes ]]; then
  sieve twin --n "$n" --k "$kmin:$kmax" --pmax "$pmax" --newpgen -j 2 > "$work/one-run.npg"
  cmp "$work/twin.npg" "$work/one-run.npg"
  echo "the merge equals one run byte for byte"
fi
