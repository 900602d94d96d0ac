#!/usr/bin/env bats
# Command-line behaviour of riesel: input formats, forms, normalisation,
# threads and shards, the --state directory (journal, lresults.txt,
# checkpoints, lock), signals, errors. Expected values come from hand
# derivations, published facts or PARI/GP, never from the tool itself; the
# bulk comparisons with PARI live in riesel_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  RES64_GP="$TOOLKIT_ROOT/test/oracle/riesel_res64.gp"
}

# The seed's prime: one LLR proof of 36625 iterations. The tests that
# interrupt it run it on GMP's squares (LONG), about 1.1 s here in release
# and sanitized builds alike (GMP is not instrumented): on the weighted
# transform it takes about 0.55 s, too short for a signal sent half a
# second in, or for a kill after 22000 iterations, to land in the proof.
SEED='778965587811*2^36627-1'
LONG=(--arithmetic gmp)

# long_input: the seed between short records of every kind, as long.txt.
long_input() {
  printf '%s\n' '5*2^100-1' "$SEED" '3*2^200+1' '6*2^10-1' '7*2^4-1' '100003' > long.txt
}

# long_reference: the uninterrupted run of long.txt with --state, computed
# once per file: want.out (stdout) and want.lresults (Time fields removed).
long_reference() {
  long_input
  if [ ! -s "$BATS_FILE_TMPDIR/want.lresults" ]; then
    riesel "${LONG[@]}" --state "$BATS_FILE_TMPDIR/ref" long.txt > "$BATS_FILE_TMPDIR/want.out"
    no_time < "$BATS_FILE_TMPDIR/ref/lresults.txt" > "$BATS_FILE_TMPDIR/want.lresults"
  fi
  cp "$BATS_FILE_TMPDIR/want.out" want.out
  cp "$BATS_FILE_TMPDIR/want.lresults" want.lresults
}

# no_seconds: records with the "seconds" value replaced by S.
no_seconds() {
  sed -E 's/"seconds":[0-9.eE+-]+/"seconds":S/'
}

# no_time: lresults.txt lines without their "  Time : S sec." or "  Time : M ms." tail.
no_time() {
  sed -E 's/  Time : [0-9]+\.[0-9]{3} (sec|ms)\.$//'
}


# checkpoint_iteration DIR: the iteration a checkpoint in DIR has reached
# (third line of the "riesel-checkpoint 1" format), 0 while there is none.
# Checkpoints are DIR/checkpoint-<16 hex digits>; a ".tmp" is one being written.
# saved_checkpoints DIR: the checkpoints in DIR, never a temporary (whose name
# also ends in a digit).
saved_checkpoints() {
  compgen -G "$1/checkpoint-*" | grep -E '/checkpoint-[0-9a-f]{16}$' || true
}

checkpoint_iteration() {
  local file iteration
  for file in $(saved_checkpoints "$1"); do
    iteration=$(sed -n 3p "$file" 2>/dev/null)
    [[ "$iteration" =~ ^[0-9]+$ ]] && echo "$iteration" && return 0
  done
  echo 0
}

# seed_seconds FILE: the "seconds" of the seed's record in FILE.
seed_seconds() {
  python3 -c '
import json, sys
for r in map(json.loads, open(sys.argv[1])):
    if r.get("n") == 36627: print(r["seconds"])' "$1"
}

need_gp() {
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
}

# oracle_gp < SCRIPT: PARI/GP with the helpers of test/oracle/riesel_res64.gp.
oracle_gp() {
  gp -q -f "$RES64_GP"
}

# ------------------------------------------------------------ help, version, usage

@test "--help prints usage on stdout and exits 0" {
  run --separate-stderr riesel --help
  assert_success
  assert_output --partial "Usage: riesel"
  for option in --start --arithmetic --require-proof --state --checkpoint-every --shard --skip-bad --max-bits --csv --threads --proof-threads; do
    assert_output --partial -- "$option"
  done
  [ -z "$stderr" ]
}

@test "--version names the tool" {
  run riesel --version
  assert_success
  assert_output --regexp '^riesel \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
}

@test "unknown options and bad option values are usage errors with exit 2" {
  run riesel --no-such-option
  assert_failure 2
  assert_output --partial "Try 'riesel --help' for more information."
  run riesel --start lucas < /dev/null
  assert_failure 2
  assert_output --partial "Try 'riesel --help'"
  run riesel -j 0 < /dev/null
  assert_failure 2
  assert_output --partial "Try 'riesel --help'"
}

# ------------------------------------------------------------ verdicts and fields

# 3*2^11-1 = 6143 is prime (A002235 has 11); 3 | k, so P is Rodseth's: P = 3
# works, as (1/N) = 1 and (5/N) = (N/5) = (3/5) = -1. 7*2^4-1 = 111 = 3*37.
# 3*2^2+1 = 13 is prime: a = 3 and 4 are squares mod 13, (5/13) = (3/5) = -1.
@test "k*2^n-1 gets LLR and k*2^n+1 Proth: fields in a fixed order after the record's own" {
  cat > in.jsonl <<'EOF'
{"id":"a","k":3,"b":2,"n":11,"c":-1}
{"id":"b","k":3,"b":2,"n":2,"c":1,"note":[1]}
{"k":7,"b":2,"n":4,"c":-1}
EOF
  riesel in.jsonl | no_seconds > got.txt
  run cat got.txt
  assert_output '{"id":"a","k":3,"b":2,"n":11,"c":-1,"verdict":"prime","test":"llr","P":3,"seconds":S}
{"id":"b","k":3,"b":2,"n":2,"c":1,"note":[1],"verdict":"prime","test":"proth","a":5,"seconds":S}
{"k":7,"b":2,"n":4,"c":-1,"verdict":"composite","test":"trial","witness":"factor 3","seconds":S}'
}

@test "a composite proved by LLR or Proth carries res64, P or a, from PARI" {
  need_gp
  run oracle_gp <<'GP'
print("composite llr ", llr_P(5, 100), " ", hex64(llr_residue(5, 100, llr_P(5, 100))));
print("composite proth ", proth_a(3, 200), " ", hex64(proth_residue(3, 200, proth_a(3, 200))));
GP
  assert_success
  want=$output
  run bash -c "printf '5*2^100-1\n3*2^200+1\n' | riesel | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"verdict\"], r[\"test\"], r.get(\"P\", r.get(\"a\")), r[\"res64\"])'"
  assert_success
  assert_output "$want"
  assert_output --regexp ' [0-9A-F]{16}$'
}

@test "expressions, {\"number\"} and {\"expr\"} records: numbers of no k*2^n+-1 shape never get more than probable-prime" {
  # 100003 is prime and neither k*2^n-1 nor k*2^n+1 with k < 2^n;
  # 3^40*2^90-1 has the factor 11 (3^40 = 1 mod 11 and 2^90 = 1 mod 11).
  printf '{"number":"100003"}\n{"expr":"3^40*2^90-1"}\n' > in.jsonl
  run bash -c "riesel in.jsonl | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"verdict\"], r[\"test\"], r.get(\"witness\", \"-\"))'"
  assert_success
  assert_output "probable-prime bpsw -
composite trial factor 11"
}

@test "a number written out in digits that is k*2^n+-1 gets LLR or Proth, like its expression" {
  # 2^127-1 (a Mersenne prime) in decimal; 6143 = 3*2^11-1 and 12289 =
  # 3*2^12+1 (both prime: A002235 and A002253 have n = 11 and 12);
  # 6151 = 3*2^11+7 is not of the shape (prime: BPSW).
  printf '{"number":"170141183460469231731687303715884105727"}\n' > in.jsonl
  printf '6143\n12289\n6151\n' > in.txt
  run bash -c "riesel in.jsonl in.txt | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"verdict\"], r[\"test\"])'"
  assert_success
  assert_output "prime llr
prime llr
prime proth
probable-prime bpsw"
  # Proved as 3*2^11-1 and 3*2^12+1, but logged by the digits they were given as.
  run bash -c "printf '6143\n12289\n' | riesel --state st > /dev/null && cut -d' ' -f1-3 st/lresults.txt"
  assert_output "6143 is prime!
12289 is prime!"
}

@test "CSV in and out: a header row with the tool's columns" {
  printf 'id,k,b,n,c\nx,3,2,11,-1\ny,7,2,4,-1\n' > in.csv
  run riesel --csv in.csv
  assert_success
  assert_line --index 0 'id,k,b,n,c,verdict,test,P,a,res64,witness,seconds,members'
  assert_line --index 1 --regexp '^x,3,2,11,-1,prime,llr,3,,,,[0-9.e-]+,$'
  assert_line --index 2 --regexp '^y,7,2,4,-1,composite,trial,,,,factor 3,[0-9.e-]+,$'
}

# ------------------------------------------------------------ forms

# 3*2^2-1 = 11, 3*2^3-1 = 23, 3*2^4-1 = 47 are prime and 3*2^5-1 = 95 = 5*19;
# 3*2^2+1 = 13. 1*2^1+1 = 3, 1*2^2+1 = 5 and 1*2^3+1 = 9 = 3*3. 5*2^1-1 = 9.
@test "forms list their members, prove each and stop at the first composite" {
  cat > forms.jsonl <<'EOF'
{"k":3,"n":2,"form":"twin"}
{"k":3,"n":2,"form":"sg"}
{"k":3,"n":2,"form":"cc1","length":4}
{"k":1,"n":1,"form":"cc2","length":3}
{"k":5,"n":1,"form":"twin"}
EOF
  run bash -c "riesel forms.jsonl | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin):
    print(r[\"verdict\"], r[\"test\"], json.dumps(r[\"members\"], separators=(\",\", \":\")))'"
  assert_success
  assert_line --index 0 'prime proth [{"n":2,"c":-1,"verdict":"prime","test":"llr","P":5},{"n":2,"c":1,"verdict":"prime","test":"proth","a":5}]'
  assert_line --index 1 'prime llr [{"n":2,"c":-1,"verdict":"prime","test":"llr","P":5},{"n":3,"c":-1,"verdict":"prime","test":"llr","P":3}]'
  assert_line --index 2 'composite trial [{"n":2,"c":-1,"verdict":"prime","test":"llr","P":5},{"n":3,"c":-1,"verdict":"prime","test":"llr","P":3},{"n":4,"c":-1,"verdict":"prime","test":"llr","P":3},{"n":5,"c":-1,"verdict":"composite","test":"trial","witness":"factor 5"}]'
  assert_line --index 3 'composite trial [{"n":1,"c":1,"verdict":"prime","test":"proth","a":5},{"n":2,"c":1,"verdict":"prime","test":"proth","a":3},{"n":3,"c":1,"verdict":"composite","test":"trial","witness":"factor 3"}]'
  assert_line --index 4 'composite trial [{"n":1,"c":-1,"verdict":"composite","test":"trial","witness":"factor 3"}]'
}

# Members of sieve's survivors at n = 100 (pmax well below their square
# root, so many are composite): every format gives the same records and
# verdicts, and the verdicts are PARI's (every member must be prime).
@test "sieve's NewPGen, ABC, ABCD, CSV and JSON Lines output piped into riesel: same verdicts, PARI's" {
  skip_volume_when_sanitized
  need_gp
  set -o pipefail
  forms=("twin --k 1:30000 --pmax 1e5" "sg --k 1:2000 --pmax 1e4" "cc1 --length 3 --k 1:30000 --pmax 1e5"
         "cc2 --length 2 --k 1:30000 --pmax 1e5" "riesel --k 1:2000 --pmax 1e4" "proth --k 1:2000 --pmax 1e4")
  for i in "${!forms[@]}"; do
    for format in json --newpgen --abc --abcd --csv; do
      sieve ${forms[$i]} --n 100 ${format#json} | riesel -j 2 > "out.$i$format"
    done
  done
  # Each output as "k n verdict [member proofs]" (riesel and proth lines of
  # ABC files are plain k*2^n+-1 records, with the proof on the record), and
  # a PARI line per record: prime when every member is.
  python3 - out.* <<'PY'
import json, sys
keys = ("verdict", "test", "P", "a", "res64", "witness")
for path in sys.argv[1:]:
    with open(path) as f, open(path + ".txt", "w") as out:
        for r in map(json.loads, f):
            members = r.get("members") or [r]
            print(r["k"], r["n"], r["verdict"], json.dumps([{x: m[x] for x in keys if x in m} for m in members]), file=out)
PY
  for i in "${!forms[@]}"; do
    [ "$(wc -l < "out.${i}json.txt")" -gt 5 ]
    for format in --newpgen --abc --abcd --csv; do
      run diff "out.${i}json.txt" "out.$i$format.txt"
      assert_success
    done
    name=${forms[$i]%% *}
    length=$(sed -nE 's/.*--length ([0-9]+).*/\1/p' <<< "${forms[$i]}")
    cut -d' ' -f1,2 "out.${i}json.txt" | while read -r k n; do
      echo "print(if(vecmin(apply(isprime, members(\"$name\", ${length:-1}, $k, $n))), \"prime\", \"composite\"));"
    done
  done > verdicts.gp
  gp -q > want.txt <<GP
members(form, len, k, n) = {
  if(form == "twin", [k*2^n-1, k*2^n+1],
     form == "sg", [k*2^n-1, k*2^(n+1)-1],
     form == "cc1", vector(len, i, k*2^(n+i-1)-1),
     form == "cc2", vector(len, i, k*2^(n+i-1)+1),
     form == "riesel", [k*2^n-1],
     [k*2^n+1]);
}
$(cat verdicts.gp)
GP
  for i in "${!forms[@]}"; do cut -d' ' -f3 "out.${i}json.txt"; done > got.txt
  run diff want.txt got.txt
  assert_success
  [ "$(grep -c '^prime$' want.txt)" -gt 20 ]
}

@test "NewPGen twin lines keep k, n and form: sieve twin ... --newpgen | riesel" {
  set -o pipefail
  sieve twin --n 100 --k 1:2000 --pmax 1e4 --newpgen > twin.npg
  sieve twin --n 100 --k 1:2000 --pmax 1e4 --newpgen | riesel > out.jsonl
  run bash -c "python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"k\"], r[\"n\"], r[\"form\"])' < out.jsonl"
  assert_success
  assert_output "$(tail -n +2 twin.npg | sed 's/$/ twin/')"
  [ "${#lines[@]}" -gt 5 ]
}

# ------------------------------------------------------------ normalisation and fallbacks

# 6*2^10-1 = 12*2^9-1 = 3*2^11-1 = 6143 (prime; P = 3 as above). 6*2^1+1 =
# 3*2^2+1 = 13. 14*2^100-1 = 7*2^101-1: LLR's P = 4 and PARI's residue.
# lresults.txt names each number as the input wrote it, as LLR 4 does.
@test "an even k is proved as k/2, n+1 (P, res64), while lresults names the number as given" {
  need_gp
  printf '6*2^10-1\n12*2^9-1\n6*2^1+1\n14*2^100-1\n7*2^101-1\n' > even.txt
  run bash -c "riesel --state st even.txt | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"k\"], r[\"n\"], r[\"verdict\"], r[\"test\"], r.get(\"P\", r.get(\"a\")), r.get(\"res64\", \"-\"))'"
  assert_success
  res64=$(oracle_gp <<< 'print(hex64(llr_residue(7, 101, llr_P(7, 101))));')
  assert_output "6 10 prime llr 3 -
12 9 prime llr 3 -
6 1 prime proth 5 -
14 100 composite llr 4 $res64
7 101 composite llr 4 $res64"
  run no_time < st/lresults.txt
  assert_output "6*2^10-1 is prime! (4 decimal digits)
12*2^9-1 is prime! (4 decimal digits)
6*2^1+1 is prime! (2 decimal digits)
14*2^100-1 is not prime.  LLR Res64: $res64
7*2^101-1 is not prime.  LLR Res64: $res64"
}

# 5*2^2-1 = 19 and 3*2^1+1 = 7 are prime but k >= 2^n: no proof applies.
@test "k >= 2^n falls back to BPSW: probable-prime, never prime" {
  run bash -c "printf '5*2^2-1\n3*2^1+1\n' | riesel | json-field verdict"
  assert_output "probable-prime
probable-prime"
  run bash -c "printf '5*2^2-1\n' | riesel | json-field test"
  assert_output "bpsw"
}

@test "k >= 2^n against PARI: every prime is probable-prime by BPSW, every composite composite" {
  need_gp
  # Odd k from 2^n up to 2^70, n = 1..62, both signs; PARI's ispseudoprime.
  gp -q > expected.txt <<'GP'
{
  setrand(31);
  for(i = 1, 400,
    n = 1 + random(62); k = bitor(2^n + random(2^min(70, n + 1 + random(20))), 1); c = if(random(2), 1, -1);
    N = k*2^n + c;
    print(k, "*2^", n, if(c > 0, "+1", "-1"), " ", if(ispseudoprime(N), "probable-prime", "composite")));
}
GP
  cut -d' ' -f1 expected.txt | riesel -j 2 > out.jsonl
  run diff <(cut -d' ' -f2 expected.txt) <(json-field verdict < out.jsonl)
  assert_success
  [ "$(grep -c probable-prime expected.txt)" -gt 10 ]
  run bash -c "json-field test < out.jsonl | sort -u"
  assert_output "bpsw
trial"
}

# 32769*2^17+1 = 65537^2 (k = 2^15+1 < 2^17, and 65537 is above the trial
# bound): no a has (a/N) = -1, so Proth's test has no base. Composite all the same.
@test "a Proth number that is a square is composite, without a base or res64" {
  run bash -c "echo '32769*2^17+1' | riesel | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"verdict\"], r[\"test\"], \"a\" in r, \"res64\" in r)'"
  assert_success
  assert_output "composite proth False False"
}

# 2*3^5+1 = 487 is prime; 4^2+1 = 17 is prime (and is 2^4+1, but written in base 4).
@test "--require-proof: a number with no LLR or Proth proof is an error with file:line, after the records before it" {
  # 5*2^2-1 = 19: k >= 2^n; 3*2^1-1 = 5: LLR needs n >= 2; 100003: no
  # k*2^n+-1 shape. 9*2^2-1 = 35 has the factor 5: composite is a proof.
  printf '3*2^11-1\n9*2^2-1\n5*2^2-1\n3*2^11+1\n' > in.txt
  run --separate-stderr riesel --require-proof in.txt
  assert_failure 1
  assert_line --index 0 --partial '"verdict":"prime","test":"llr"'
  assert_line --index 1 --partial '"verdict":"composite","test":"trial"'
  [ "${#lines[@]}" -eq 2 ]
  [ "$stderr" = "riesel: in.txt:3: 5*2^2-1 cannot be proved: k (made odd) is not below 2^n" ]
  run --separate-stderr bash -c "printf '{\"k\":3,\"n\":1,\"form\":\"riesel\"}\n{\"number\":\"100003\"}\n' | riesel --require-proof --skip-bad"
  assert_success
  [ -z "$output" ]
  assert_equal "$stderr" "riesel: <stdin>:1: 3*2^1-1 cannot be proved: LLR needs n >= 2
riesel: <stdin>:2: 100003 cannot be proved: it is not k*2^n-1 or k*2^n+1 with k below 2^n
riesel: skipped 2 bad records"
}

@test "other bases and other c get BPSW and at best probable-prime, unless the value is k*2^n+-1" {
  # 2*3^5+1 = 487 (prime) is no k*2^n+-1 with k < 2^n; 1*4^2+1 = 17 is
  # 1*2^4+1 and 1*2^3+3 = 11 is 3*2^2-1, both proved.
  printf '{"k":2,"b":3,"n":5,"c":1}\n{"k":1,"b":4,"n":2,"c":1}\n{"k":1,"b":2,"n":3,"c":3}\n' > other.jsonl
  run bash -c "riesel other.jsonl | python3 -c '
import json, sys
for r in map(json.loads, sys.stdin): print(r[\"verdict\"], r[\"test\"])'"
  assert_success
  assert_output "probable-prime bpsw
prime proth
prime llr"
}

# {"k":1,"n":1,"form":"riesel"} is 1*2^1-1 = 1: not prime, and n < 2 means no LLR.
@test "n < 2 in a riesel form: 1 is composite by BPSW; 3*2^1-1 = 5 falls back to BPSW" {
  run bash -c "printf '{\"k\":1,\"n\":1,\"form\":\"riesel\"}\n{\"k\":3,\"n\":1,\"form\":\"riesel\"}\n{\"k\":1,\"n\":1,\"form\":\"proth\"}\n' | riesel | json-field members"
  assert_success
  assert_line --index 0 --regexp '^\[\{"n": 1, "c": -1, "verdict": "composite", "test": "bpsw"'
  assert_line --index 1 '[{"n": 1, "c": -1, "verdict": "probable-prime", "test": "bpsw"}]'
  # 1*2^1+1 = 3: Proth works from n = 1 (a = 5, as 3 | 3 and 4 is a square).
  assert_line --index 2 '[{"n": 1, "c": 1, "verdict": "prime", "test": "proth", "a": 5}]'
}

@test "numbers below 2 are composite with mrtest's witness 'n < 2', not a factor that does not divide them" {
  run --separate-stderr bash -c "printf '0\n-7\n1\n-1\n' | riesel --state st"
  assert_success
  run python3 -c '
import json, sys
rows = [json.loads(line) for line in sys.argv[1].splitlines()]
assert [(r["verdict"], r["witness"]) for r in rows] == [("composite", "n < 2")] * 4, rows
print("ok")' "$output"
  assert_output ok
  run grep -c ' is not prime\.  n < 2  Time' st/lresults.txt
  assert_output 4
}

@test "3 = 2^2-1 = 1*2^2-1 is prime (LLR with n = 2)" {
  run bash -c "echo '2^2-1' | riesel | json-field verdict"
  assert_output "prime"
  run bash -c "echo '{\"k\":2,\"b\":2,\"n\":1,\"c\":-1}' | riesel | json-field verdict"
  assert_output "prime"
  run bash -c "echo '{\"k\":1,\"n\":2,\"form\":\"twin\"}' | riesel | json-field verdict"
  assert_output "prime"
}

@test "an even k is normalised even when n = 0 or k has more than 64 bits" {
  run bash -c "printf '{\"k\":8,\"b\":2,\"n\":0,\"c\":-1}\n{\"k\":\"18446744073709551616\",\"b\":2,\"n\":63,\"c\":-1}\n' | riesel | json-field verdict"
  assert_output "prime
prime"
}

# ------------------------------------------------------------ --start

@test "--start d13 uses P = 11 when (13/N) = -1 and is an error otherwise; --skip-bad goes on" {
  need_gp
  # k*2^100-1 without a factor below 1000 (trial division would answer
  # first): PARI's (13/N) decides which are allowed.
  run oracle_gp <<< 'forstep(k = 1, 99, 2, N = k*2^100 - 1; if(no_small_factor(N), print(k, " ", kronecker(13, N))));'
  minus=$(awk '$2 == -1 { print $1; exit }' <<< "$output")
  plus=$(awk '$2 == 1 { print $1; exit }' <<< "$output")
  [ -n "$minus" ] && [ -n "$plus" ]
  run bash -c "echo '$minus*2^100-1' | riesel --start d13 | json-field P"
  assert_success
  assert_output "11"
  run riesel --start d13 <<< "$plus*2^100-1"
  assert_failure 1
  assert_output --regexp '^riesel: <stdin>:1: .*13'
  printf '%s\n' "$plus*2^100-1" "$minus*2^100-1" > mixed.txt
  run --separate-stderr riesel --start d13 --skip-bad mixed.txt
  assert_success
  [[ "$stderr" == *"mixed.txt:1:"* ]]
  assert_output --partial "\"k\":$minus,"
  [ "${#lines[@]}" -eq 1 ]
}

# ------------------------------------------------------------ threads and shards

# mixed.abc: sieve's riesel survivors at n = 300 (LLR proofs of all kinds).
mixed_input() {
  sieve riesel --n 300 --k 1:3000 --pmax 1e4 --abc > mixed.abc
  [ "$(wc -l < mixed.abc)" -gt 200 ]
}

@test "-j 1 and -j 2 write the same records in input order (seconds aside)" {
  mixed_input
  riesel -j 1 mixed.abc | no_seconds > one.txt
  riesel -j 2 mixed.abc | no_seconds > two.txt
  run cmp one.txt two.txt
  assert_success
  [ "$(wc -l < one.txt)" -eq $(( $(wc -l < mixed.abc) - 1 )) ]
  grep -q '"verdict":"prime"' one.txt
  grep -q '"res64"' one.txt
}

# Known primes (3*2^n-1 at n = 4204, 3*2^n+1 at n = 3912) and composites
# that pass trial division, proved with every squaring split over two
# threads (the crossover lowered to any length): the records -t 1 writes.
@test "-t 2 splits each proof's squarings and writes what -t 1 writes" {
  printf '%s\n' '3*2^4204-1' '3*2^3912+1' '3*2^4206-1' '3*2^3914+1' '16869987339975*2^3001-1' > split.txt
  riesel --arithmetic fft split.txt | no_seconds > one.txt
  TOOLKIT_PROOF_THREADS_FROM=1 riesel -t 2 --arithmetic fft split.txt | no_seconds > two.txt
  run cmp one.txt two.txt
  assert_success
  [ "$(grep -c '"verdict":"prime"' two.txt)" -eq 2 ]
  sed -n 1p two.txt | grep -q '"n":4204.*"verdict":"prime"'
  sed -n 2p two.txt | grep -q '"n":3912.*"verdict":"prime"'
  TOOLKIT_PROOF_THREADS_FROM=1 riesel -j 2 -t 2 --arithmetic fft split.txt | no_seconds > both.txt
  run cmp one.txt both.txt
  assert_success
}

@test "-t 0 is a usage error" {
  run riesel -t 0 <<< '3*2^4204-1'
  assert_failure 2
}

@test "--shard K/3 proves records K, K+3, ...: the three shards make up one run" {
  mixed_input
  riesel mixed.abc | no_seconds > single.txt
  for i in 1 2 3; do
    riesel --shard $i/3 mixed.abc | no_seconds > shard$i.txt
    awk -v i=$i 'NR % 3 == i % 3' single.txt > want$i.txt
    run cmp shard$i.txt want$i.txt
    assert_success
  done
  run cmp <(sort shard1.txt shard2.txt shard3.txt) <(sort single.txt)
  assert_success
  # --shard 1/1 is the whole run.
  riesel --shard 1/1 mixed.abc | no_seconds > all.txt
  run cmp all.txt single.txt
  assert_success
}

@test "shards run through GNU parallel make up one run" {
  command -v parallel >/dev/null || skip "GNU parallel is not installed"
  mixed_input
  dir=$BATS_TEST_TMPDIR
  parallel --will-cite riesel --shard {}/3 "$dir/mixed.abc" '>' "$dir"/p{}.jsonl ::: 1 2 3 < /dev/null
  riesel mixed.abc | no_seconds | sort > single.txt
  run cmp <(cat p1.jsonl p2.jsonl p3.jsonl | no_seconds | sort) single.txt
  assert_success
}

# ------------------------------------------------------------ --state: journal and lresults.txt

# LLR 4.0.6's shapes (Llr.c: isLLRP, GerbiczTest, write_timer): its Proth
# residue is a^((N-1)/2) mod N plus one, with "Base-a " when a is not 3.
@test "lresults.txt has LLR's line shapes, with PARI's residues" {
  need_gp
  # LLR prime, LLR composite, Proth prime, Proth composite, trial, BPSW.
  printf '3*2^11-1\n5*2^100-1\n3*2^2+1\n3*2^200+1\n7*2^4-1\n100003\n' > in.txt
  riesel --state st in.txt > /dev/null
  run cat st/lresults.txt
  local time='  Time : [0-9]+\.[0-9]{3} (sec|ms)\.$'
  assert_line --index 0 --regexp "^3\\*2\\^11-1 is prime! \\(4 decimal digits\\)$time"
  assert_line --index 1 --regexp "^5\\*2\\^100-1 is not prime\\.  LLR Res64: [0-9A-F]{16}$time"
  assert_line --index 2 --regexp "^3\\*2\\^2\\+1 is prime! \\(2 decimal digits\\)$time"
  assert_line --index 3 --regexp "^3\\*2\\^200\\+1 is not prime\\.  Base-7 Proth RES64: [0-9A-F]{16}\\.$time"
  assert_line --index 4 --regexp "^7\\*2\\^4-1 is not prime\\.  factor 3$time"
  assert_line --index 5 --regexp "^100003 is a BPSW probable prime\\. \\(6 decimal digits\\)$time"
  [ "${#lines[@]}" -eq 6 ]
  run oracle_gp <<'GP'
print(hex64(llr_residue(5, 100, llr_P(5, 100))), " ", proth_a(3, 200), " ", hex64(proth_residue(3, 200, proth_a(3, 200)) + 1), " ", isprime(100003));
GP
  read -r llr a proth isprime <<< "$output"
  [ "$isprime" = 1 ] && [ "$a" = 7 ]
  grep -qx "5\*2^100-1 is not prime.  LLR Res64: $llr  Time : .*" st/lresults.txt
  grep -qx "3\*2^200+1 is not prime.  Base-7 Proth RES64: $proth.  Time : .*" st/lresults.txt
}

# A sieve file names even k (sieve keeps every k of the range): lresults.txt
# must name 1338*2^1000-1 so, not 669*2^1001-1, for scripts that match
# results to the sieve file. PARI evaluates each name and checks it is the
# input line's number, and recomputes its residue from that number alone.
@test "sieve files: lresults names each number as its line gave it (even k too), and PARI agrees" {
  need_gp
  printf '1000:M:1:2:2\n1338 1000\n' > one.npg
  riesel --state st1 one.npg > /dev/null
  run no_time < st1/lresults.txt
  assert_output --regexp '^1338\*2\^1000-1 is not prime\.  LLR Res64: [0-9A-F]{16}$'
  sieve riesel --n 1000 --k 1:60 --pmax 1e3 --newpgen > r.npg
  sieve proth --n 1000 --k 1:60 --pmax 1e3 --abc > p.abc
  grep -q '^8 1000$' r.npg  # even k are among them
  riesel --state st r.npg p.abc > out.jsonl
  # One GP check per record: name, k, n, c, and what the line says.
  python3 - st/lresults.txt out.jsonl > checks.gp <<'PY'
import json, re, sys
lines = open(sys.argv[1]).read().splitlines()
records = [json.loads(l) for l in open(sys.argv[2])]
assert len(lines) == len(records), (len(lines), len(records))
for line, r in zip(lines, records):
    m = re.fullmatch(r"(\S+) is (prime! \(\d+ decimal digits\)|not prime\.  (LLR Res64: ([0-9A-F]{16})|(Base-(\d+) )?Proth RES64: ([0-9A-F]{16})\.))  Time : \d+\.\d{3} (sec|ms)\.", line)
    assert m, line
    name, kind = m.group(1), "prime" if m.group(2).startswith("prime") else ("llr" if m.group(4) else "proth")
    res = m.group(4) or m.group(7) or ""
    base = m.group(6) or "3"
    print(f'check("{name}", {r["k"]}, {r["n"]}, {r["c"]}, "{kind}", "{res}", {base});')
PY
  run oracle_gp < <(cat - checks.gp <<'GP'
check(name, k, n, c, kind, res, a) = {
  my(N = eval(name), v, h);
  if (N != k*2^n + c, error("named ", name, " but tested ", k, "*2^", n, c));
  v = valuation(N - c, 2); h = (N - c) >> v;
  if (kind == "prime", if (!ispseudoprime(N), error(name, " is not prime")); return);
  if (kind == "llr", if (res != hex64(llr_residue(h, v, llr_P(h, v))), error(name, ": LLR Res64")); return);
  if (a != proth_a(h, v) || res != hex64(proth_residue(h, v, a) + 1), error(name, ": Proth RES64"));
}
GP
  echo 'print("checked ", '"$(wc -l < checks.gp)"');')
  assert_success
  assert_output "checked $(wc -l < checks.gp)"
  grep -q '^8\*2^1000-1 is ' st/lresults.txt
}

@test "form members each get an lresults line, up to the first composite" {
  printf '{"k":3,"n":2,"form":"cc1","length":4}\n' | riesel --state st > /dev/null
  run no_time < st/lresults.txt
  assert_output "3*2^2-1 is prime! (2 decimal digits)
3*2^3-1 is prime! (2 decimal digits)
3*2^4-1 is prime! (2 decimal digits)
3*2^5-1 is not prime.  factor 5"
}

@test "a re-run with the same --state replays the journal: same stdout byte for byte, no new proofs" {
  long_reference
  cp -r "$BATS_FILE_TMPDIR/ref" st
  cp st/lresults.txt lresults.before
  run --separate-stderr riesel "${LONG[@]}" --state st long.txt
  assert_success
  # Equal "seconds" too: the records come from the journal, not new proofs.
  [ "$output" = "$(cat "$BATS_FILE_TMPDIR/want.out")" ]
  run cmp st/lresults.txt lresults.before
  assert_success
}

@test "a second run on a --state directory in use fails with exit 1 and names the lock" {
  long_input
  riesel "${LONG[@]}" --state st long.txt > /dev/null 2> first.err 3>&- &
  pid=$!
  wait_for st/lock
  wait_for_handler "$pid"
  run riesel "${LONG[@]}" --state st long.txt
  assert_failure 1
  assert_output --regexp '^riesel: st(/)?: .*lock'
  [ "${#lines[@]}" -eq 1 ]
  kill -INT "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 130 ]
  # The first run is gone: the directory is free again.
  run bash -c "echo '3*2^11-1' | riesel --state st | json-field verdict"
  assert_success
  assert_output "prime"
}

@test "a re-run with another --start does not replay the other start's records" {
  need_gp
  k=$(oracle_gp <<< 'forstep(k = 1, 99, 2, N = k*2^100 - 1; if(kronecker(13, N) == -1 && no_small_factor(N), print(k); break));')
  riesel --state st <<< "$k*2^100-1" > /dev/null
  # Either a proof with P = 11, or a refusal to mix starts in one directory.
  run --separate-stderr bash -c "set -o pipefail; riesel --state st --start d13 <<< '$k*2^100-1' | json-field P"
  if [ "$status" -eq 0 ]; then
    assert_output "11"
  else
    [[ "$stderr" == *start* ]]
  fi
}

@test "a torn last journal line (a crash mid-append) is dropped, and later runs still read the journal" {
  printf '5*2^100-1\n3*2^11-1\n7*2^101-1\n' > in.txt
  riesel --state st in.txt | no_seconds > want.txt
  # Cut the last line in its output half, as a crash during the append would.
  size=$(stat -c %s st/journal.tsv)
  truncate -s $((size - 60)) st/journal.tsv
  run riesel --state st in.txt
  assert_success
  for attempt in second third; do
    run --separate-stderr riesel --state st in.txt
    assert_success
    [ "$(no_seconds <<< "$output")" = "$(cat want.txt)" ]
  done
  # The record cut off was proved again, once.
  [ "$(grep -c '^7\*2^101-1 is not prime' st/lresults.txt)" -eq 2 ]
}

@test "two records sharing a member, proved at once with --state, do not trip over each other's checkpoints" {
  # 3*2^25690-1 is prime (A002235). Three attempts, for the race; one under
  # the sanitizers, where each takes ~20 s.
  attempts=3
  if sanitized; then attempts=1; fi
  for ((attempt = 1; attempt <= attempts; ++attempt)); do
    rm -rf st
    run --separate-stderr bash -c "set -o pipefail; printf '3*2^25690-1\n3*2^25690-1\n' | riesel -j 2 --state st --checkpoint-every 0.1 | json-field verdict"
    assert_success
    assert_output "prime
prime"
  done
}

# ------------------------------------------------------------ checkpoints and signals

@test "kill -9 during a proof, then a re-run: same verdicts and lresults.txt as one run, resumed from the checkpoint" {
  long_reference
  started=$(date +%s%N)
  riesel "${LONG[@]}" --state st --checkpoint-every 0.1 long.txt > first.out 2> /dev/null 3>&- &
  pid=$!
  wait_for "st/checkpoint-????????????????"
  # Wait for 22000 of the 36625 iterations, so resuming shows; the ~0.3 s
  # of squarings left cover the polling's delay on a loaded machine (at
  # 27000 the proof sometimes ended before the kill).
  tries=1200
  while [ "$(checkpoint_iteration st)" -lt 22000 ]; do
    tries=$((tries - 1))
    [ "$tries" -gt 0 ] || { echo "no checkpoint past 22000"; false; }
    sleep 0.05
  done
  first_ms=$(( ($(date +%s%N) - started) / 1000000 ))
  kill -9 "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 137 ]
  # Killed mid-proof: the first record is out, the seed is not.
  [ "$(wc -l < first.out)" -le 1 ]
  run --separate-stderr riesel "${LONG[@]}" --state st --checkpoint-every 0.1 long.txt
  assert_success
  echo "$output" > got.out
  run cmp <(no_seconds < got.out) <(no_seconds < want.out)
  assert_success
  run cmp <(no_time < st/lresults.txt) want.lresults
  assert_success
  # Resumed, not restarted: the last 14625 iterations or so take about two
  # thirds of the time the first 22000 took (a restart would take 5/3 of it).
  resumed=$(seed_seconds got.out)
  python3 -c "import sys; sys.exit(0 if 1000 * $resumed < 1.1 * $first_ms else 1)" ||
    { echo "resumed proof $resumed s; 22000 iterations took $first_ms ms"; false; }
  # Finished proofs leave no checkpoint behind.
  run saved_checkpoints st
  assert_output ""
}

@test "SIGTERM and SIGINT save a checkpoint and kill riesel by the signal; a re-run completes" {
  long_reference
  # SIGTERM, then SIGINT, each half a second into a fresh search (a
  # resumed proof can end before a fixed delay on a fast machine), then a
  # run that resumes from SIGINT's checkpoint to the end.
  for signal in TERM INT; do
    rm -rf st
    riesel "${LONG[@]}" --state st long.txt > out.$signal 2> err.$signal 3>&- &
    pid=$!
    wait_for_handler "$pid"
    before=$(checkpoint_iteration st)
    # Into the seed's proof (the records before it take microseconds).
    sleep 0.5
    kill -"$signal" "$pid"
    status=0
    wait "$pid" || status=$?
    if [ "$signal" = INT ]; then [ "$status" -eq 130 ]; else [ "$status" -eq 143 ]; fi
    run cat err.$signal
    assert_output --regexp "^riesel: stopped by signal [0-9]+; state saved"
    # The checkpoint holds the proof's progress, beyond where it started.
    [ "$(checkpoint_iteration st)" -gt "$before" ]
    run grep -c '"n":36627' out.$signal
    assert_output "0"
  done
  run --separate-stderr riesel "${LONG[@]}" --state st long.txt
  assert_success
  echo "$output" > got.out
  run cmp <(no_seconds < got.out) <(no_seconds < want.out)
  assert_success
  # The same lines as one run (the records after the seed may have been
  # logged while the proof was stopped, so the order can differ).
  run cmp <(no_time < st/lresults.txt | sort) <(sort want.lresults)
  assert_success
}

@test "SIGINT without --state says nothing is saved and exits 130" {
  echo "$SEED" > seed.txt
  riesel "${LONG[@]}" seed.txt > out.txt 2> err.txt 3>&- &
  pid=$!
  wait_for_handler "$pid"
  sleep 0.2
  kill -INT "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 130 ]
  run cat err.txt
  assert_output --regexp "^riesel: stopped by signal 2"
  refute_output --partial "state saved"
  [ ! -s out.txt ]
}

@test "SIGINT while riesel waits for input or output still kills it by the signal" {
  mkfifo in.fifo
  riesel in.fifo > out.txt 2> err.txt 3>&- &
  pid=$!
  exec 4> in.fifo  # riesel has opened it and now waits for a line
  wait_for_handler "$pid"
  sleep 0.2
  kill -INT "$pid"
  status=0
  wait "$pid" || status=$?
  exec 4>&-
  [ "$status" -eq 130 ]
  run cat err.txt
  assert_output --regexp "^riesel: stopped by signal 2"
}

# Two proofs at once (-j 2) of primes from A002235, 3*2^18819-1 and
# 3*2^25690-1 (about 0.5 and 1 s here), each with a checkpoint when riesel is
# killed: one gets a hex digit of its saved residue changed (trusted, it would
# turn the prime into a composite), the other random bytes over all of it.
@test "damaged checkpoints are reported and ignored: the proofs start again and give the right verdicts" {
  # Two proofs of about half a second each on GMP's squares (LONG): both
  # checkpoints stay for ~0.4 s (3*2^18819-1 took 0.23 s, and on a loaded
  # sanitized run it finished between the poll and the kill).
  printf '3*2^25690-1\n3*2^26459-1\n' > two.txt
  riesel "${LONG[@]}" -j 2 --state st --checkpoint-every 0.1 two.txt > /dev/null 2>&1 3>&- &
  pid=$!
  tries=1200
  until [ "$(saved_checkpoints st | wc -l)" -eq 2 ]; do
    tries=$((tries - 1))
    [ "$tries" -gt 0 ] || { echo "no two checkpoints"; false; }
    sleep 0.05
  done
  kill -9 "$pid"
  wait "$pid" || true
  mapfile -t checkpoints < <(saved_checkpoints st)
  python3 - "${checkpoints[0]}" <<'PY'
import sys
path = sys.argv[1]
lines = open(path).read().split("\n")
value = lines[3]
i = len(value) // 2
lines[3] = value[:i] + ("1" if value[i] != "1" else "2") + value[i + 1:]
open(path, "w").write("\n".join(lines))
PY
  size=$(stat -c %s "${checkpoints[1]}")
  head -c "$size" /dev/urandom > "${checkpoints[1]}"
  run --separate-stderr riesel "${LONG[@]}" -j 2 --state st two.txt
  assert_success
  echo "$output" > got.out
  # One warning per damaged file, naming it and the member started over.
  [ "$(grep -c '^riesel: st/checkpoint-[0-9a-f]*: checkpoint .*: proving 3\*2^[0-9]*-1 from the start$' <<< "$stderr")" -eq 2 ]
  [[ "$stderr" == *"fails its checksum"* ]]
  run json-field verdict < got.out
  assert_output "prime
prime"
  run no_time < st/lresults.txt
  assert_output "3*2^25690-1 is prime! (7734 decimal digits)
3*2^26459-1 is prime! (7966 decimal digits)"
}

# ------------------------------------------------------------ errors

@test "a malformed ABC header or ABC line is an error with file:line and exit 1" {
  printf 'ABC\n3 5\n' > empty-header.abc
  run riesel empty-header.abc
  assert_failure 1
  assert_output --regexp '^riesel: empty-header.abc:1: '
  printf 'ABC $a*2^$b-1\n3 x\n' > bad-line.abc
  run riesel bad-line.abc
  assert_failure 1
  assert_output --regexp '^riesel: bad-line.abc:2: '
  printf '1000000:T:0:2:3\n3 1\nfive 4\n' > bad.npg
  run riesel bad.npg
  assert_failure 1
  assert_line --index 0 --partial '"k":3'
  assert_line --index 1 --regexp '^riesel: bad.npg:3: '
}

@test "binary garbage is an error, not a crash" {
  # Random bytes behind a NUL, and behind a good first line.
  { printf '\0\1\2'; head -c 4096 /dev/urandom; } > garbage.bin
  run riesel garbage.bin
  assert_failure 1
  assert_output --regexp '^riesel: garbage.bin:1: '
  { echo '3*2^11-1'; printf 'x\0\1\2'; head -c 4096 /dev/urandom; } > late.bin
  run riesel late.bin
  assert_failure 1
  assert_line --index 0 --partial '"verdict":"prime"'
  assert_line --index 1 --regexp '^riesel: late.bin:2: '
}

# mrtest passes a Latin-1 byte in a CSV field through (and reports bad
# records with file:line); riesel dies while making the record's journal key.
@test "invalid UTF-8 in a record (CSV field, random bytes) is no internal error" {
  run bash -c "printf 'id,number\n\xff,7\n' | riesel | json-field verdict"
  assert_success
  assert_output "prime"  # 7 = 1*2^3-1: LLR
  for seed in 3 15 21 30; do
    python3 -c "
import random, sys
random.seed($seed)
sys.stdout.buffer.write(bytes(random.randrange(256) for _ in range(4096)))" > random.bin
    run riesel random.bin
    [ "$status" -le 1 ]
    refute_output --partial "internal error"
  done
}

@test "empty input gives no output and exit 0" {
  run --separate-stderr riesel < /dev/null
  assert_success
  assert_output ""
  : > empty.txt
  run riesel --state st empty.txt
  assert_success
  assert_output ""
}

@test "numbers beyond --max-bits are refused with exit 1" {
  run riesel <<< "2^99999999999-1"
  assert_failure 1
  assert_output --partial "more than --max-bits"
  run riesel --max-bits 100 <<< "3*2^200-1"
  assert_failure 1
  assert_output --regexp '^riesel: <stdin>:1: '
  run riesel --max-bits 100 <<< '{"k":3,"n":200,"form":"twin"}'
  assert_failure 1
  run bash -c "riesel --max-bits 300 <<< '3*2^200-1' | json-field test"
  assert_success
}

@test "bad --shard values are usage errors (exit 2)" {
  for shard in 0/2 3/2 1/0 x 2/x; do
    run riesel --shard "$shard" <<< "97"
    assert_failure 2
    assert_output --partial -- "--shard"
  done
}

@test "--checkpoint-every: a value that is not positive, or no --state to keep checkpoints in, is a usage error" {
  for seconds in 0 -1 x nan; do
    run riesel --state st --checkpoint-every "$seconds" <<< "97"
    assert_failure 2
    assert_output --partial -- "--checkpoint-every"
  done
  run riesel --checkpoint-every 5 <<< "97"
  assert_failure 2
  assert_line --index 0 "riesel: --checkpoint-every needs --state"
  run riesel --state st --checkpoint-every 0.5 <<< "97"
  assert_success
}

@test "a malformed line stops with file:line after the records before it; --skip-bad goes on" {
  printf '7*2^4-1\n3*2^11-1\n12+\n3*2^2+1\n' > bad.txt
  run riesel bad.txt
  assert_failure 1
  assert_line --index 0 --partial '"n":4'
  assert_line --index 1 --partial '"n":11'
  assert_line --index 2 --regexp '^riesel: bad.txt:3: '
  [ "${#lines[@]}" -eq 3 ]
  run --separate-stderr riesel --skip-bad bad.txt
  assert_success
  [[ "$stderr" == *"bad.txt:3:"* ]]
  [ "${#lines[@]}" -eq 3 ]
}

@test "--skip-bad: riesel and mrtest warn alike, in input order, and end with the same summary" {
  printf '7*2^4-1\n12+\n3*2^11-1\n{"number": NaN}\n3*2^2+1\n' > bad.txt
  for tool in riesel mrtest; do
    run --separate-stderr "$tool" -j 2 --skip-bad bad.txt missing.txt
    assert_failure 1
    [ "${#lines[@]}" -eq 3 ]
    printf '%s\n' "$stderr" | sed "s/^$tool: //" > "$tool.err"
  done
  diff riesel.err mrtest.err
  run cat riesel.err
  assert_line --index 0 --regexp '^bad.txt:2: '
  assert_line --index 1 --regexp '^bad.txt:4: '
  assert_line --index 2 --regexp '^missing.txt: cannot open'
  assert_line --index 3 "skipped 2 bad records"
  assert_line --index 4 "1 input file was not read"
  [ "${#lines[@]}" -eq 5 ]
}

@test "a missing file, a write error and a --state that is a file are reported" {
  run riesel no-such-file.txt
  assert_failure 1
  assert_output "riesel: no-such-file.txt: cannot open: No such file or directory"
  run bash -c "echo 97 | riesel > /dev/full"
  assert_failure 1
  assert_output --partial "write error"
  : > not-a-dir
  run riesel --state not-a-dir <<< "97"
  assert_failure 1
  assert_output --partial "not-a-dir"
}
