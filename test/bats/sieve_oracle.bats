#!/usr/bin/env bats
# sieve against independent oracles written in PARI/GP:
#   test/oracle/sieve_survivors.gp  brute force: every member of every
#       candidate tested on its own (gcd with the product of the primes);
#   test/oracle/sieve_factors.gp    the expected --factors lines, prime by prime;
# and gp's own forprime/primepi for `sieve primes`.

bats_require_minimum_version 1.5.0

setup_file() {
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
}

setup() {
  load test_helper
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
  cd "$BATS_TEST_TMPDIR"
  ORACLE="$TOOLKIT_ROOT/test/oracle"
}

# gp_case ARGS...: the sieve arguments (plain integers) as a sieve_survivors.gp
# case [form, length, n, [kmin, kmax] or [h0, c, xmin, xmax], pmax]. Options the
# oracle does not model (-j, --shard) are ignored; PRIMES, when set, replaces
# pmax by a vector of prime ranges.
gp_case() {
  local form=$1 length=2 n="" k="" h0="" c="" x="" pmax=""
  shift
  while [ $# -gt 0 ]; do
    case $1 in
      --n) n=$2; shift 2 ;;
      --length) length=$2; shift 2 ;;
      --k) k=$2; shift 2 ;;
      --h0) h0=$2; shift 2 ;;
      --c) c=$2; shift 2 ;;
      --x) x=$2; shift 2 ;;
      --pmax) pmax=$2; shift 2 ;;
      *) shift ;;
    esac
  done
  local kspec
  if [ -n "$k" ]; then kspec="[${k%%:*},${k##*:}]"; else kspec="[$h0,$c,${x%%:*},${x##*:}]"; fi
  printf '["%s",%s,%s,%s,%s]' "$form" "$length" "$n" "$kspec" "${PRIMES:-$pmax}"
}

# survivors_agree CASE...: each CASE is one line of sieve arguments. Every case
# runs through sieve (JSON Lines, then json-field k), all of them through one
# gp session of sieve_survivors.gp, and the two lists must be equal. A record
# {"k":"# case i"} stands for the oracle's separator line.
survivors_agree() {
  local cases="" i=0 line
  : > got.jsonl
  for line in "$@"; do
    i=$((i + 1))
    cases+="${cases:+,}$(gp_case $line)"
    printf '{"k":"# case %d"}\n' "$i" >> got.jsonl
    sieve $line ${SIEVE_OPTIONS:-} > one.jsonl || { echo "sieve $line: exit $?"; return 1; }
    grep -v '^// sieve shard ' one.jsonl >> got.jsonl || true  # a --shard run's last line is no record
  done
  json-field k < got.jsonl > got.txt
  { echo "CASES=[$cases];"; cat "$ORACLE/sieve_survivors.gp"; } | gp -q -f > want.txt
  [ "$(grep -c '^# case' want.txt)" -eq "$i" ] || { echo "gp failed"; cat want.txt; return 1; }
  diff want.txt got.txt
}

# The standard grid: n = 1..12 and 100, pmax 1000 and 50000, k = 1..3000.
# Small n with pmax 50000 gives members that are themselves primes below pmax.
grid() {
  local n pmax
  for n in 1 2 3 4 5 6 7 8 9 10 11 12 100; do
    for pmax in 1000 50000; do echo "$* --n $n --k 1:3000 --pmax $pmax"; done
  done
}

# check_grid FORM...: the grid for one form agrees with the oracle, which
# keeps some but not all candidates.
check_grid() {
  mapfile -t cases < <(grid "$@")
  run survivors_agree "${cases[@]}"
  assert_success
  survivors=$(grep -vc '^#' want.txt)
  [ "$survivors" -gt 26 ]
  [ "$survivors" -lt $((26 * 3000 / 2)) ]
}

@test "twin: n = 1..12 and 100, pmax 1000 and 50000, k = 1..3000 agree with PARI" {
  check_grid twin
}

@test "sg: n = 1..12 and 100, pmax 1000 and 50000, k = 1..3000 agree with PARI" {
  check_grid sg
}

@test "cc1 --length 2: the grid agrees with PARI" {
  check_grid cc1 --length 2
}

@test "cc1 --length 3: the grid agrees with PARI" {
  check_grid cc1 --length 3
}

@test "cc2 --length 2: the grid agrees with PARI" {
  check_grid cc2 --length 2
}

@test "cc2 --length 3: the grid agrees with PARI" {
  check_grid cc2 --length 3
}

@test "riesel: the grid agrees with PARI" {
  check_grid riesel
}

@test "proth: the grid agrees with PARI" {
  check_grid proth
}

@test "pmax 3*10^6 (primes above 2^20, in blocks) agrees with PARI for every form, -j 2" {
  cases=()
  for form in twin sg "cc1 --length 2" "cc1 --length 3" "cc2 --length 2" "cc2 --length 3" riesel proth; do
    cases+=("$form --n 100 --k 1:3000 --pmax 3000000" "$form --n 7 --k 100001:102000 --pmax 3000000")
  done
  SIEVE_OPTIONS="-j 2" run survivors_agree "${cases[@]}"
  assert_success
  # The primes above 2^20 did remove candidates.
  sieve riesel --n 100 --k 1:3000 --pmax 3000000 --factors riesel.txt > /dev/null
  [ "$(awk '$1 > 1048576' riesel.txt | wc -l)" -gt 3 ]
}

@test "parametrised k = h0 + c*x (c = 30, 2310, 30030) agrees with PARI" {
  run survivors_agree \
    "twin --n 7 --h0 15 --c 30 --x 0:3000 --pmax 50000" \
    "twin --n 100 --h0 1155 --c 2310 --x 5:3000 --pmax 3000000" \
    "sg --n 12 --h0 1155 --c 2310 --x 1000:4000 --pmax 50000" \
    "cc1 --length 3 --n 60 --h0 15015 --c 30030 --x 0:3000 --pmax 50000" \
    "cc2 --length 2 --n 9 --h0 1155 --c 2310 --x 0:3000 --pmax 1000" \
    "riesel --n 64 --h0 3 --c 30 --x 0:3000 --pmax 50000" \
    "proth --n 3 --h0 1 --c 2 --x 0:3000 --pmax 1000" \
    "proth --n 20 --h0 3 --c 77 --x 0:3000 --pmax 3000000"
  assert_success
  [ "$(grep -vc '^#' want.txt)" -gt 100 ]
}

# "Prime Hunting" (seed 000, section 3.1): h0 = 0, c = 30030, the Cc22
# project's own choice; every k = 30030x is even, so each candidate is also
# (k/2^t)*2^(n+t)+-1. The records keep k = h0 + c*x.
@test "the paper's parametrisation h0 = 0, c = 30030 (every k even) agrees with PARI for every form" {
  run survivors_agree \
    "cc2 --length 2 --n 5 --h0 0 --c 30030 --x 1:3000 --pmax 50000" \
    "cc2 --length 2 --n 64 --h0 0 --c 30030 --x 1:3000 --pmax 3000000" \
    "cc2 --length 3 --n 20 --h0 0 --c 30030 --x 1:3000 --pmax 50000" \
    "cc1 --length 2 --n 12 --h0 0 --c 30030 --x 1:3000 --pmax 50000" \
    "twin --n 1 --h0 0 --c 30030 --x 1:3000 --pmax 50000" \
    "sg --n 7 --h0 0 --c 30030 --x 1:3000 --pmax 1000" \
    "riesel --n 100 --h0 0 --c 30030 --x 1:3000 --pmax 50000" \
    "proth --n 2 --h0 0 --c 30030 --x 1:3000 --pmax 1000"
  assert_success
  survivors=$(grep -vc '^#' want.txt)
  [ "$survivors" -gt 1000 ]
  # Every survivor's k is even, as written.
  [ "$(json-field k < got.jsonl | grep -c '^[0-9]*[02468]$')" -eq "$survivors" ]
}

@test "edge cases agree with PARI: k near 2^64, exponents near 64, tiny pmax, prime members above 2^20" {
  run survivors_agree \
    "riesel --n 1 --k 524000:530000 --pmax 1100000" \
    "proth --n 2 --k 1048000:1051000 --pmax 4300000" \
    "twin --n 100 --k 1:3000 --pmax 1048583" \
    "twin --n 5 --k 18446744073709549616:18446744073709551615 --pmax 50000" \
    "proth --n 1 --k 18446744073709549616:18446744073709551615 --pmax 1000" \
    "sg --n 63 --k 1:3000 --pmax 50000" \
    "cc2 --length 3 --n 62 --k 1:3000 --pmax 50000" \
    "cc1 --length 4 --n 61 --k 1:3000 --pmax 1000" \
    "riesel --n 64 --k 1:3000 --pmax 50000" \
    "cc1 --length 4 --n 1 --k 1:3000 --pmax 3" \
    "cc2 --length 5 --n 1 --k 1:3000 --pmax 7" \
    "twin --n 1 --k 1:3000 --pmax 8"
  assert_success
}

@test "the scalar and AVX2 root kernels agree with PARI too" {
  cases=("twin --n 100 --k 1:3000 --pmax 50000" "cc1 --length 3 --n 5 --k 1:3000 --pmax 3000000"
         "sg --n 12 --h0 1155 --c 2310 --x 0:3000 --pmax 50000")
  for kernel in scalar avx2; do
    TOOLKIT_SIEVE_KERNEL=$kernel run survivors_agree "${cases[@]}"
    assert_success
  done
}

# Block 1024 of a --shard run, [2^20 + 1 + 1024*2^22, 2^20 + 1025*2^22], is the
# first one above 2^32 (blocks are 2^22 wide and start above 2^20): shard
# 1025/1025 sieves the primes up to 2^20 and that block only. gp picks a k
# (or x) whose members survive 2^20 and the first block prime that divides one.
@test "a --shard run over primes above 2^32 agrees with PARI" {
  high=$((1048576 + 1025 * 4194304))
  export PRIMES="[[3,2^20],[2^20+1+1024*2^22,$high]]"
  read -r p k0 x0 < <(gp -q -f <<'GP'
default(debugmem, 0); default(parisizemax, 2^30);
L = 2^20 + 1 + 1024*2^22; P = vecprod(primes([3, 2^20])); n = 100;
ok(k) = gcd(k*2^n - 1, P) == 1 && gcd(k*2^n + 1, P) == 1;
p = nextprime(L); while(1, k = lift(Mod(2, p)^-n); if(ok(k), break); p = nextprime(p + 1));
q = nextprime(L); while(1, x = lift((Mod(-1, q)/Mod(2, q)^n - 1155)/2310); if(ok(1155 + 2310*x), break); q = nextprime(q + 1));
print(p, " ", k, " ", x);
GP
)
  [ "$p" -gt 4294967296 ]
  run survivors_agree \
    "twin --n 100 --k $((k0 - 1500)):$((k0 + 1500)) --pmax $high --shard 1025/1025" \
    "twin --n 100 --h0 1155 --c 2310 --x $((x0 - 1500)):$((x0 + 1500)) --pmax $high --shard 1025/1025"
  assert_success
  # The chosen k was removed, by the block prime gp found.
  sieve twin --n 100 --k $((k0 - 1500)):$((k0 + 1500)) --pmax $high --shard 1025/1025 --factors f.txt > /dev/null
  run grep -c "^$p | $k0\*2^100-1$" f.txt
  assert_output "1"
}

# ------------------------------------------------------------ --factors

# factors_agree ARGS...: sieve ARGS --factors writes exactly the lines of
# sieve_factors.gp (compared sorted), every line is checked on its own by gp
# (p prime, p <= pmax, p | k*2^e+c), each removed k appears once, and the
# removed and surviving k make up the whole range.
factors_agree() {
  local form=$1 n=$2 kmin=$3 kmax=$4 pmax=$5
  sieve "$form" --n "$n" --k "$kmin:$kmax" --pmax "$pmax" -j 2 --factors factors.txt | json-field k > survivors.txt
  { echo "FORM=\"$form\"; N=$n; KMIN=$kmin; KMAX=$kmax; PMAX=$pmax;"; cat "$ORACLE/sieve_factors.gp"; } | gp -q -f | sort > want.txt
  sort factors.txt > got.txt
  diff want.txt got.txt || return 1
  # Line by line: "p | k*2^e+c" -> [p, k, e, c].
  sed -E 's/^([0-9]+) \| ([0-9]+)\*2\^([0-9]+)([+-]1)$/[\1,\2,\3,\4],/' factors.txt > vectors.txt
  [ "$(grep -vc '^\[' vectors.txt)" -eq 0 ] || { echo "malformed lines"; return 1; }
  bad=$({ echo "default(debugmem, 0);"; echo "default(parisizemax, 2^30);"
          echo "v = [$(tr -d '\n' < vectors.txt | sed 's/,$//')];"
          echo "print(#select(r -> !(isprime(r[1]) && r[1] <= $pmax && Mod(r[2], r[1])*Mod(2, r[1])^r[3] + r[4] == 0), v))"; } | gp -q -f)
  [ "$bad" = 0 ] || { echo "$bad lines fail"; return 1; }
  cut -d' ' -f3 factors.txt | cut -d'*' -f1 | sort -n > removed.txt
  [ -z "$(uniq -d removed.txt)" ] || { echo "a k is removed twice"; return 1; }
  sort -n removed.txt survivors.txt > all.txt
  seq "$kmin" "$kmax" | diff - all.txt
}

@test "--factors for twin n = 171960, k <= 2000, pmax 10^6: PARI's lines, each valid, covering the range" {
  run factors_agree twin 171960 1 2000 1000000
  assert_success
  [ "$(wc -l < survivors.txt)" -gt 0 ]
}

@test "--factors with pmax 1.5*10^6 (above 2^20) for twin n = 1000 and sg n = 5000: PARI's lines, each valid" {
  # 3*10^4 k: enough survivors of 2^20 for primes above it to remove some (4 here).
  run factors_agree twin 1000 1 30000 1500000
  assert_success
  [ "$(awk '$1 > 1048576' factors.txt | wc -l)" -gt 1 ]
  run factors_agree sg 5000 1 20000 1500000
  assert_success
}

# ------------------------------------------------------------ primes

@test "sieve primes --count: pi(10^6) = 78498, pi(10^9) = 50847534" {
  run sieve primes 1 1e6 --count
  assert_success
  assert_output "78498"
  run sieve primes 1 1e9 --count
  assert_output "50847534"
  run sieve primes 1 1000000000 --count -j 2
  assert_output "50847534"
  run sieve primes 1e9 1e9 --count
  assert_output "0"
}

@test "sieve primes --count: pi(10^10) = 455052511" {
  [[ "$TOOLKIT_BIN" != *sanitize* ]] || skip "slow under the sanitizers"
  run sieve primes 1 1e10 --count -j 2
  assert_success
  assert_output "455052511"
}

@test "sieve primes 1 1000 is gp's forprime(p = 1, 1000)" {
  gp -q -f <<< 'forprime(p = 1, 1000, print(p))' > want.txt
  sieve primes 1 1000 > got.txt
  run diff want.txt got.txt
  assert_success
  [ "$(wc -l < got.txt)" -eq 168 ]
}

@test "sieve primes 10^12 .. 10^12+10^5 is gp's list, and --count its length" {
  gp -q -f <<< 'forprime(p = 10^12, 10^12 + 10^5, print(p))' > want.txt
  sieve primes 1e12 1000000100000 -j 2 > got.txt
  run diff want.txt got.txt
  assert_success
  run sieve primes 1e12 1000000100000 --count
  assert_output "$(wc -l < want.txt)"
  gp -q -f <<< 'forprime(p = 2^40 - 10^4, 2^40 + 10^4, print(p))' > want.txt
  sieve primes 1099511617776 1099511637776 > got.txt
  run diff want.txt got.txt
  assert_success
}

@test "sieve primes up to 2^64-1 lists gp's primes" {
  # (--count of the same interval does give gp's 21; primesieve needs about
  # 3 s for an interval up there, so this test runs only the listing.)
  gp -q -f <<< 'forprime(p = 2^64 - 1000, 2^64 - 1, print(p))' > want.txt
  sieve primes 18446744073709550616 18446744073709551615 > got.txt
  run diff want.txt got.txt
  assert_success
}
