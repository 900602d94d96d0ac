#!/usr/bin/env bats
# Fault injection for sieve: runs killed (kill -9 and SIGTERM) at random
# moments and resumed, two runs on one checkpoint, a stop while the small
# primes sieve, and what a killed run leaves behind. The references are
# uninterrupted runs and, for the survivors, PARI/GP.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

need_gp() {
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
}

# About 1 s a shard here: 2*10^4 candidates, primes up to 4*10^8.
RUN="twin --n 1000 --k 1:2e4 --pmax 4e8 --newpgen"

# complete_or_refused FILE REFERENCE OTHER: FILE is either the whole shard
# (byte for byte REFERENCE) or a file that sieve merge refuses next to
# the other shard OTHER; never a part that merges.
complete_or_refused() {
  if cmp -s "$1" "$2"; then return 0; fi
  run sieve merge "$1" "$3"
  [ "$status" -eq 1 ] || { echo "a killed run left $1 ($(wc -c < "$1") bytes), and merge took it: $output"; return 1; }
}

@test "shards killed with -9 or SIGTERM at random moments and resumed merge to the uninterrupted run" {
  seed=${SIEVE_FAULT_SEED:-$$}
  RANDOM=$seed
  echo "seed $seed (SIEVE_FAULT_SEED repeats it)"
  sieve $RUN > single.npg
  sieve $RUN --shard 1/2 --factors want1.factors > want1.npg
  sieve $RUN --shard 2/2 --factors want2.factors > want2.npg
  [ "$(wc -l < single.npg)" -gt 10 ]
  for i in 1 2; do
    other=want$((3 - i)).npg
    for kill_round in 1 2 3 4 5 6; do
      sieve $RUN --shard $i/2 --factors got$i.factors --checkpoint ck$i --checkpoint-every 0.05 --resume \
        > got$i.npg 2> /dev/null 3>&- &
      pid=$!
      sleep "0.$(printf '%02d' $((RANDOM % 100)))"
      signal=$([ $((kill_round % 2)) -eq 0 ] && echo KILL || echo TERM)
      kill -"$signal" "$pid" 2> /dev/null || true
      status=0
      wait "$pid" || status=$?
      [ "$status" -eq 0 ] || [ "$status" -eq 137 ] || [ "$status" -eq 143 ]
      complete_or_refused got$i.npg want$i.npg "$other"
    done
    # Whatever the kills left, the last resume finishes the shard as one run would.
    sieve $RUN --shard $i/2 --factors got$i.factors --checkpoint ck$i --resume > got$i.npg
    run cmp got$i.npg want$i.npg
    assert_success
    run cmp got$i.factors want$i.factors
    assert_success
    run compgen -G "ck$i.tmp"
    assert_failure
  done
  sieve merge got1.npg got2.npg > merged.npg
  run cmp merged.npg single.npg
  assert_success
}

@test "the uninterrupted run the kill test compares with keeps exactly the twins without a factor up to pmax (PARI/GP)" {
  need_gp
  args="twin --n 1000 --k 1:300 --pmax 2e5"
  sieve $args --newpgen --shard 1/2 > s1.npg
  sieve $args --newpgen --shard 2/2 > s2.npg
  sieve merge s1.npg s2.npg | tail -n +2 | cut -d' ' -f1 > got.txt
  echo 'for(k=1,300,my(ok=1);forprime(p=3,200000,if((k*2^1000-1)%p==0||(k*2^1000+1)%p==0,ok=0;break));if(ok,print(k)))' |
    gp -q -f > want.txt
  [ -s want.txt ]
  run diff got.txt want.txt
  assert_success
}

@test "a second sieve on the same --checkpoint is refused while the first runs; a killed holder does not block" {
  sieve twin --n 1000 --k 1:2e4 --pmax 1e11 --checkpoint ck --checkpoint-every 0.05 > /dev/null 2> first.err 3>&- &
  pid=$!
  wait_for ck
  run timeout 60 sieve twin --n 1000 --k 1:2e4 --pmax 1e11 --checkpoint ck --resume  # (a hang guard)
  assert_failure 1
  assert_output --regexp "^sieve: ck: another run holds this checkpoint's lock"
  kill -9 "$pid"
  wait "$pid" || true
  # What a run killed mid-save may leave: the next run removes it.
  echo partial > ck.tmp
  run --separate-stderr sieve twin --n 1000 --k 1:3000 --pmax 3e6 --checkpoint ck --newpgen
  assert_success
  [ ! -e ck.tmp ]
  [ "$(head -1 <<< "$output")" = "3000000:T:0:2:3" ]
}

@test "SIGTERM while the small primes sieve saves their segments; --resume gives the uninterrupted output" {
  # 6*10^7 candidates are 29 segments of 2^21 (a second or more at -j 1); the
  # first checkpoint comes after the first segment. pmax 1.1*10^6 adds one
  # small block of larger primes.
  args="twin --n 1000 --k 1:6e7 --pmax 1.1e6 --newpgen"
  # (No --factors: nearly every candidate would write a line, 650 MB. The
  # unit test SieveFiles.CheckpointInTheSmallPrimePhase checks them.)
  sieve $args > want.npg
  sieve $args -j 1 --checkpoint ck --checkpoint-every 0.01 > out.npg 2> err.txt 3>&- &
  pid=$!
  wait_for ck
  kill -TERM "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 143 ]
  run cat err.txt
  assert_output --regexp "^sieve: stopped by signal 15 while the primes up to 2\^20 sieved, after [0-9]+ of 29 segments; checkpoint saved"
  [ ! -s out.npg ]
  sieve $args -j 2 --checkpoint ck --resume > got.npg
  run cmp got.npg want.npg
  assert_success
}
