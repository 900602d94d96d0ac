#!/usr/bin/env bats
# mrtest against what "Prime Hunting" (Farkas, Kiss, Papatyi, Schaffer; seed
# 000, section 2.2) prints: its Miller-Rabin test and Theorem 2.3 (under
# GRH, a composite n > 8 that is no prime power has a witness a < 2 (ln n)^2).
# The oracle is PARI/GP: Miller-Rabin written in GP from the paper's text,
# and isprime; the pseudoprime lists come from test/oracle/pseudoprimes.cpp.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
  cd "$BATS_TEST_TMPDIR"
}

# The paper: n = 1 + q*2^k with q odd; n passes to base a iff a^q = 1 or
# a^(q*2^j) = -1 (mod n) for some 0 <= j <= k-1.
GP_MR='spsp(n, a) = { my(k = valuation(n - 1, 2), q = (n - 1) >> k, b = Mod(a, n)^q);
  if(b == 1, return(1)); for(j = 0, k - 1, if(b == -1, return(1)); b = b^2); 0 };
least_witness(n) = { my(a = 2); while(spsp(n, a), a++); a };'

@test "--test mr is the paper's Miller-Rabin, base by base (bases 2..13, odd n up to 10^30)" {
  { echo "$GP_MR"; cat <<'GP'
setrand(5);
v = concat(vector(150, i, 2*random(10^6) + 3), vector(150, i, 2*random(10^30) + 1));
v = concat(v, [2047, 1373653, 25326001, 3215031751, 2152302898747, 3474749660383, 341550071728321]);
foreach(v, n, print(n, " ", vector(12, i, spsp(n, i + 1))));
GP
  } | gp -q -f | sed 's/, /,/g' > want.txt
  cut -d' ' -f1 want.txt > numbers.txt
  for a in 2 3 4 5 6 7 8 9 10 11 12 13; do
    # (sed rather than json-field: twelve Python starts would cost more than the tests)
    mrtest -t mr -b "$a" --trial-bound 0 numbers.txt | sed -E 's/.*"verdict":"([a-z-]+)".*/\1/; s/probable-prime/1/; s/composite/0/' > "b$a.txt"
  done
  paste -d, b2.txt b3.txt b4.txt b5.txt b6.txt b7.txt b8.txt b9.txt b10.txt b11.txt b12.txt b13.txt | sed 's/^/[/; s/$/]/' > got.txt
  run diff <(cut -d' ' -f2 want.txt) got.txt
  assert_success
  # Strong pseudoprimes are in the mix: some composite passes some base.
  [ "$(grep -c 1 got.txt)" -gt 25 ]
}

# gp's expected line for n: "composite perfect power" (the theorem leaves
# prime powers out; mr-grh tests for powers first), "prime-if-grh" when
# isprime(n), else "composite base A" with A the least witness.
GP_GRH='grh(n) = if(ispower(n), "composite perfect power", isprime(n), "prime-if-grh", Str("composite base ", least_witness(n)));'

@test "--test mr-grh (Theorem 2.3) agrees with PARI's isprime, and its witness is the least one" {
  run "$TOOLKIT_BUILD/test/pseudoprimes" --limit 1e9 lists
  assert_success
  { echo "$GP_MR"; echo "$GP_GRH"; echo "v = [$(cat lists/spsp2.txt lists/carmichael.txt | paste -sd,)];"; cat <<'GP'
setrand(7);
\\ psi_9 (a strong pseudoprime to every prime base up to 31), psi_12 (up to
\\ 37), psi_13 (up to 41): gp checks that they pass those bases.
psis = [3825123056546413051, 318665857834031151167461, 3317044064679887385961981];
top = [31, 37, 41];
for(i = 1, 3, forprime(p = 2, top[i], if(!spsp(psis[i], p), error("psi ", i, " fails ", p))));
v = concat(v, psis);
v = concat(v, [3^7, 1194649 * 3, 7^2 * 11^2]);
v = concat(v, vector(3000, i, 10^12 + 2*i - 1));
v = concat(v, vector(20, i, randomprime([10^19, 10^30])));
v = concat(v, vector(20, i, randomprime([10^9, 10^15]) * randomprime([10^9, 10^15])));
foreach(v, n, print(n, " ", grh(n)));
GP
  } | gp -q -f > want.txt
  cut -d' ' -f1 want.txt > numbers.txt
  mrtest -j 2 -t mr-grh --trial-bound 0 numbers.txt > got.jsonl
  paste -d' ' <(json-field number < got.jsonl) <(json-field verdict < got.jsonl) <(json-field witness < got.jsonl) |
    sed 's/ $//' > got.txt
  run diff want.txt got.txt
  assert_success
  # The mix: primes, spsp(2) with Wieferich squares (perfect powers) among them, Carmichael numbers.
  [ "$(grep -c 'prime-if-grh$' want.txt)" -gt 100 ]
  [ "$(grep -c 'perfect power$' want.txt)" -ge 3 ]
  [ "$(grep -c 'composite base' want.txt)" -gt 2000 ]
  # Some least witnesses are large: base 2 alone would not do.
  [ "$(awk '$3 == "base" && $4 > 13' want.txt | wc -l)" -ge 3 ]
}
