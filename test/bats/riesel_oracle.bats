#!/usr/bin/env bats
# riesel's verdicts and residues against independent oracles: PARI/GP
# (ispseudoprime, and the LLR and Proth residues recomputed from their
# definitions in test/oracle/riesel_res64.gp), the OEIS and published primes.
# The command-line behaviour (formats, state, signals, errors) is in riesel.bats.

setup_file() {
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
}

setup() {
  load test_helper
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
  cd "$BATS_TEST_TMPDIR"
  RES64_GP="$TOOLKIT_ROOT/test/oracle/riesel_res64.gp"
}

# oracle_gp < SCRIPT: PARI/GP with the helpers of riesel_res64.gp loaded.
oracle_gp() {
  gp -q -f "$RES64_GP"
}

# primes_n: the "n" of every record whose verdict is prime, one line.
primes_n() {
  python3 -c '
import json, sys
print(" ".join(str(r["n"]) for r in map(json.loads, sys.stdin) if r["verdict"] == "prime"))'
}

# 3*2^n-1 is OEIS A002235 and 3*2^n+1 is A002253. Up to 2000 (n >= 2):
# A002235: 2 3 4 6 7 11 18 34 38 43 55 64 76 94 103 143 206 216 306 324 391 458 470 827 1274
# A002253: 2 5 6 8 12 18 30 36 41 66 189 201 209 276 353 408 438 534
# k = 3 < 2^n for n >= 2, so every one gets a proof (Rodseth's P, since 3 | k;
# Proth's a), never BPSW. Under the sanitizers the range stops at 1300.
@test "3*2^n-1 (A002235) and 3*2^n+1 (A002253), n = 2..2000: riesel's primes are PARI's and the OEIS's" {
  max=2000
  [[ "$TOOLKIT_BIN" == *sanitize* ]] && max=1300
  oeis_minus="2 3 4 6 7 11 18 34 38 43 55 64 76 94 103 143 206 216 306 324 391 458 470 827 1274"
  oeis_plus="2 5 6 8 12 18 30 36 41 66 189 201 209 276 353 408 438 534"
  for c in -1 +1; do
    seq 2 "$max" | sed "s/.*/3*2^&$c/" > in.txt
    riesel -j 2 in.txt > out.jsonl
    [ "$(wc -l < out.jsonl)" -eq $((max - 1)) ]
    got=$(primes_n < out.jsonl)
    want=$(echo "for(n = 2, $max, if(ispseudoprime(3*2^n $c), print(n)));" | gp -q | paste -sd' ')
    [ "$got" = "$want" ] || { echo "c = $c: riesel: $got"; echo "c = $c: PARI:   $want"; false; }
    if [ "$c" = -1 ]; then oeis=$oeis_minus; else oeis=$oeis_plus; fi
    oeis=$(echo "$oeis" | tr ' ' '\n' | awk -v m="$max" '$1 <= m' | paste -sd' ')
    [ "$got" = "$oeis" ]
    # Proofs only: prime or composite, by llr/proth or trial division.
    run bash -c "json-field verdict < out.jsonl | sort -u"
    assert_output "composite
prime"
    run bash -c "json-field test < out.jsonl | sort -u"
    if [ "$c" = -1 ]; then assert_output "llr
trial"; else assert_output "proth
trial"; fi
  done
}

# The "Prime Hunting" seed's number 778965587811*2^36627-1 is prime. It ends a
# Cunningham chain of the first kind of length 3: 778965587811*2^36625-1 and
# 778965587811*2^36626-1 are prime as well (PARI's ispseudoprime says so, in
# 16-20 s each here: too slow for this suite; RIESEL_ORACLE_FULL=1 runs it,
# and the proof of n = 36625). n = 36624 and 36628 have the factor 5, n =
# 36629 the factor 11839.
@test "778965587811*2^n-1: n = 36626 and 36627 (and 36625) prime by LLR; 36628 and 36629 composite" {
  ns="36626 36627 36628 36629"
  [ -n "${RIESEL_ORACLE_FULL:-}" ] && ns="36625 $ns"
  for n in $ns; do echo "778965587811*2^$n-1"; done | riesel -j 2 > out.jsonl
  python3 -c '
import json, sys
for r in map(json.loads, sys.stdin):
    print(r["n"], r["verdict"], r["test"], r.get("P", "-"), r.get("witness", "-"), "res64" in r)' < out.jsonl > got.txt
  # LLR's P for each proof (3 | k: Rodseth's rule), from PARI.
  oracle_gp > want.txt <<GP
{
  k = 778965587811;
  foreach([$(echo $ns | tr ' ' ,)], n,
    if(n == 36628, print(n, " composite trial - factor 5 False"),
       n == 36629, print(n, " composite llr ", llr_P(k, n), " - True"),
       print(n, " prime llr ", llr_P(k, n), " - False")));
}
GP
  run diff want.txt got.txt
  assert_success
  # PARI: the factors that make 36624, 36628 and 36629 composite.
  run gp -q <<< 'k = 778965587811; print((k*2^36628 - 1) % 5, " ", (k*2^36629 - 1) % 11839, " ", (k*2^36624 - 1) % 5);'
  assert_output "0 0 0"
  if [ -n "${RIESEL_ORACLE_FULL:-}" ]; then
    run gp -q <<< 'k = 778965587811; print(vector(3, i, ispseudoprime(k*2^(36624 + i) - 1)));'
    assert_output "[1, 1, 1]"
  fi
}

# OpenPFGW's test vectors: twins 1327691127*2^4502 +- 1, and the Cunningham
# chain of the first kind 582320115*2^4428-1, 2^4429-1, 2^4430-1 (4427 and
# 4431 are composite, so the chain has length 3 exactly).
@test "OpenPFGW vectors: twin 1327691127*2^4502+-1 and the cc1 chain 582320115*2^4428-1 of length 3" {
  run gp -q <<< 'print(ispseudoprime(1327691127*2^4502-1), ispseudoprime(1327691127*2^4502+1), vector(5, i, ispseudoprime(582320115*2^(4426 + i) - 1)));'
  assert_output "11[0, 1, 1, 1, 0]"
  cat > forms.jsonl <<'EOF'
{"k":1327691127,"n":4502,"form":"twin"}
{"k":582320115,"n":4428,"form":"cc1","length":3}
{"k":582320115,"n":4428,"form":"cc1","length":4}
{"k":582320115,"n":4427,"form":"cc1","length":4}
EOF
  riesel -j 2 forms.jsonl > out.jsonl
  run json-field verdict < out.jsonl
  assert_output "prime
prime
composite
composite"
  run bash -c "python3 -c '
import json, sys
for r in map(json.loads, sys.stdin):
    print(\" \".join(\"%s%+d:%s:%s\" % (m[\"n\"], m[\"c\"], m[\"verdict\"], m[\"test\"]) for m in r[\"members\"]))' < out.jsonl"
  assert_line --index 0 "4502-1:prime:llr 4502+1:prime:proth"
  assert_line --index 1 "4428-1:prime:llr 4429-1:prime:llr 4430-1:prime:llr"
  assert_line --index 2 --regexp "^4428-1:prime:llr 4429-1:prime:llr 4430-1:prime:llr 4431-1:composite:(llr|trial)$"
  # The first member is composite: the chain stops there.
  assert_line --index 3 --regexp "^4427-1:composite:(llr|trial)$"
}

# The seed's D = 13 start (P = 11) and LLR's start must give the same verdict
# whenever (13/N) = -1; PARI picks the numbers (k odd below 2^24, n = 100..900,
# some of them primes found by ispseudoprime) and gives its own verdict too.
@test "--start d13 and --start llr agree with PARI on random k*2^n-1 with (13/N) = -1, primes included" {
  gp -q > expected.txt <<'GP'
{
  setrand(20261122);
  count = 0;
  while(count < 150,
    k = 2*random(2^23) + 1; n = 100 + random(800); N = k*2^n - 1;
    if(kronecker(13, N) == -1, count++; print(k, "*2^", n, "-1 ", if(ispseudoprime(N), "prime", "composite"))));
  found = 0;
  while(found < 12,
    k = 2*random(2^23) + 1; n = 100 + random(400); N = k*2^n - 1;
    if(kronecker(13, N) == -1 && ispseudoprime(N), found++; print(k, "*2^", n, "-1 prime")));
}
GP
  [ "$(wc -l < expected.txt)" -eq 162 ]
  cut -d' ' -f1 expected.txt > in.txt
  riesel -j 2 --start llr in.txt > llr.jsonl
  riesel -j 2 --start d13 in.txt > d13.jsonl
  json-field verdict < llr.jsonl > llr.txt
  json-field verdict < d13.jsonl > d13.txt
  cut -d' ' -f2 expected.txt > want.txt
  run diff want.txt llr.txt
  assert_success
  run diff want.txt d13.txt
  assert_success
  [ "$(grep -c '^prime$' want.txt)" -ge 12 ]
  # Every proof by d13 used P = 11; LLR's own P differs at least once.
  run bash -c "paste <(json-field test < d13.jsonl) <(json-field P < d13.jsonl) | awk '\$1 == \"llr\"' | cut -f2 | sort -u"
  assert_output "11"
  run bash -c "paste <(json-field test < llr.jsonl) <(json-field P < llr.jsonl) | awk '\$1 == \"llr\"' | cut -f2 | sort -u | wc -l"
  [ "$output" -gt 1 ]
}

# Composites without a factor below 1000 (so the proof runs to the end): the
# residues must be the ones the definitions give (riesel_res64.gp). k ranges
# from 1 to 2^64-1, including multiples of 3 (Rodseth's P) and k near 2^n.
@test "res64 and P/a of LLR, d13 and Proth composites equal PARI's (n = 64..500, k up to 2^64-1)" {
  oracle_gp > expected.txt <<'GP'
setrand(77);
pick(c) = {
  my(k, n, N);
  until(k < 2^n && k < 2^64 && !ispseudoprime(N) && no_small_factor(N),
    n = 64 + random(437);
    k = 2*random(2^(1 + random(63))) + 1;
    if(random(4) == 0, k = 3*k);
    if(random(8) == 0, n = 64; k = 2^64 - 1 - 2*random(2^20));
    N = k*2^n + c);
  [k, n];
}
for(i = 1, 40, [k, n] = pick(-1); P = llr_P(k, n); print(k, "*2^", n, "-1 llr ", P, " ", hex64(llr_residue(k, n, P))));
for(i = 1, 40, [k, n] = pick(1); a = proth_a(k, n); print(k, "*2^", n, "+1 proth ", a, " ", hex64(proth_residue(k, n, a))));
GP
  oracle_gp > expected_d13.txt <<'GP'
{
  setrand(78);
  count = 0;
  while(count < 30,
    n = 64 + random(437); k = 2*random(2^(1 + random(63))) + 1; N = k*2^n - 1;
    if(k < 2^n && kronecker(13, N) == -1 && !ispseudoprime(N) && no_small_factor(N),
      count++; print(k, "*2^", n, "-1 llr 11 ", hex64(llr_residue(k, n, 11)))));
}
GP
  [ "$(wc -l < expected.txt)" -eq 80 ]
  [ "$(wc -l < expected_d13.txt)" -eq 30 ]
  # What riesel says, in the same shape: member test parameter res64.
  shape='import json, sys
for r in map(json.loads, sys.stdin):
    print(r["verdict"], r["test"], r.get("P", r.get("a")), r.get("res64"))'
  cut -d' ' -f1 expected.txt | riesel -j 2 | python3 -c "$shape" > got.txt
  cut -d' ' -f1 expected_d13.txt | riesel -j 2 --start d13 | python3 -c "$shape" > got_d13.txt
  run diff <(cut -d' ' -f2- expected.txt | sed 's/^/composite /') got.txt
  assert_success
  run diff <(cut -d' ' -f2- expected_d13.txt | sed 's/^/composite /') got_d13.txt
  assert_success
  # A few small ones spelled out (n = 100..500).
  run oracle_gp <<'GP'
print(hex64(llr_residue(5, 100, 4)), " ", hex64(llr_residue(51, 331, llr_P(51, 331))), " ", hex64(proth_residue(3, 200, proth_a(3, 200))));
GP
  assert_success
  want=$output
  run bash -c "printf '5*2^100-1\n51*2^331-1\n3*2^200+1\n' | riesel | json-field res64 | paste -sd' '"
  assert_output "$want"
}

# The weighted squaring's transforms (libshared/primes/right_angle_transform
# and FFTW's), each forced with TOOLKIT_RIESEL_TRANSFORM, on composites
# large enough for several passes: res64 and P/a from PARI's definitions.
@test "every transform (ours at AVX-512 and AVX2 width, FFTW's) gives PARI's res64 at n = 2500..6000" {
  oracle_gp > expected.txt <<'GP'
setrand(2611);
pick(c) = {
  my(k, n, N);
  until(k < 2^n && !ispseudoprime(N) && no_small_factor(N),
    n = 2500 + random(3501);
    k = 2*random(2^(random(56))) + 1;
    N = k*2^n + c);
  [k, n];
}
for(i = 1, 4, [k, n] = pick(-1); P = llr_P(k, n); print(k, "*2^", n, "-1 llr ", P, " ", hex64(llr_residue(k, n, P))));
for(i = 1, 3, [k, n] = pick(1); a = proth_a(k, n); print(k, "*2^", n, "+1 proth ", a, " ", hex64(proth_residue(k, n, a))));
GP
  [ "$(wc -l < expected.txt)" -eq 7 ]
  shape='import json, sys
for r in map(json.loads, sys.stdin):
    print(r["verdict"], r["test"], r.get("P", r.get("a")), r.get("res64"))'
  for transform in widest avx2 fftw; do
    cut -d' ' -f1 expected.txt | TOOLKIT_RIESEL_TRANSFORM=$transform riesel -j 2 --arithmetic fft | python3 -c "$shape" > got.txt
    run diff <(cut -d' ' -f2- expected.txt | sed 's/^/composite /') got.txt
    assert_success
  done
}
