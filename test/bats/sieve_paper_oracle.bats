#!/usr/bin/env bats
# sieve against what "Prime Hunting" (Farkas, Kiss, Papatyi, Schaffer; seed
# 000, section 3) prints, with PARI/GP as the independent computation:
#   the Cc22 project's h0 = 0, c = 30030, e = 256000 (every k even);
#   "no prime factors less than 17";
#   p_S = 134 217 689, the largest prime below 2^27;
#   sieve | mrtest | riesel on that parametrisation, against isprime.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
  cd "$BATS_TEST_TMPDIR"
}

# The members (30030x)*2^256000+1 and (30030x)*2^256001+1 have 77,069 digits;
# gp works modulo P, the product of the primes up to 10000, and keeps x when
# neither member shares a factor with P (a member is far above every p).
@test "the Cc22 project's h0 = 0, c = 30030, e = 256000: survivors are PARI's, and no prime below 17 removes one" {
  sieve cc2 --length 2 --n 256000 --h0 0 --c 30030 --x 1:3000 --pmax 10000 --factors f.txt | json-field x > got.txt
  gp -q -f > want.txt <<'GP'
default(parisizemax, 2^28);
P = vecprod(primes([2, 10000])); R0 = Mod(2, P)^256000; R1 = 2*R0;
for(x = 1, 3000, if(gcd(lift(30030*x*R0 + 1), P) == 1 && gcd(lift(30030*x*R1 + 1), P) == 1, print(x)));
GP
  run diff want.txt got.txt
  assert_success
  [ "$(wc -l < want.txt)" -gt 100 ]
  # The primes of c = 2*3*5*7*11*13 never divide k*2^e+1 (k = 0 mod p): the
  # smallest prime in the factors file is 17.
  [ "$(cut -d' ' -f1 f.txt | sort -n | head -1)" = 17 ]
}

@test "p_S = 134217689, the paper's small-prime bound, is the largest prime below 2^27" {
  gp -q -f <<< 'forprime(p = 2^27 - 2000, 2^27, print(p))' > want.txt
  sieve primes 134215728 134217728 > got.txt
  run diff want.txt got.txt
  assert_success
  [ "$(tail -1 got.txt)" = 134217689 ]
}

# The paper's parametrisation at e = 80 (so that the proofs take seconds):
# candidates k*2^80+1, k*2^81+1 with k = 30030x; the chain verdicts of
# mrtest (BPSW) and riesel (Proth proofs of k made odd) are PARI's isprime.
@test "sieve | mrtest | riesel on h0 = 0, c = 30030 (cc2, length 2, e = 80) give PARI's verdicts; riesel names k as given" {
  sieve cc2 --length 2 --n 80 --h0 0 --c 30030 --x 1:20000 --pmax 1e5 > cand.jsonl
  mrtest -j 2 --trial-bound 0 cand.jsonl > tested.jsonl
  json-field verdict < tested.jsonl > mrtest.txt
  mrtest -j 2 --trial-bound 0 --keep prime,probable cand.jsonl | riesel -j 2 --state st > proved.jsonl
  json-field x < cand.jsonl > xs.txt
  { echo "v = [$(paste -sd, xs.txt)];"; cat <<'GP'
foreach(v, x, k = 30030*x; print(if(isprime(k*2^80 + 1) && isprime(k*2^81 + 1), "chain", "composite")));
GP
  } | gp -q -f > want.txt
  [ "$(wc -l < want.txt)" -eq "$(wc -l < cand.jsonl)" ]
  # mrtest: probable-prime exactly for PARI's chains (members above 2^64).
  run diff <(sed 's/chain/probable-prime/' want.txt) mrtest.txt
  assert_success
  chains=$(grep -c chain want.txt)
  [ "$chains" -ge 2 ]
  # riesel proves every chain mrtest passed.
  [ "$(json-field verdict < proved.jsonl | grep -c '^prime$')" -eq "$chains" ]
  # Its results name each member as the sieve file gave it (30030x*2^80+1,
  # even k kept, as LLR 4 names them); gp writes the same names.
  grep -o '^[0-9]*\*2^[0-9]*+1' st/lresults.txt | sort > names.txt
  paste -d' ' xs.txt want.txt | awk '$2 == "chain" { print $1 }' > chain_xs.txt
  { echo "v = [$(paste -sd, chain_xs.txt)];"; cat <<'GP'
foreach(v, x, k = 30030*x; for(i = 0, 1, print(k, "*2^", 80 + i, "+1")));
GP
  } | gp -q -f | sort > want_names.txt
  run diff want_names.txt names.txt
  assert_success
}
