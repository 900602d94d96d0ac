#!/usr/bin/env bats
# riesel against what "Prime Hunting" (Farkas, Kiss, Papatyi, Schaffer; seed
# 000, section 2.1) prints: the D = 13, a = 3, b = 1 Riesel test, computed in
# PARI/GP the paper's way (quadratic integers x + y(1 + sqrt 13)/2, alpha =
# (3 + sqrt 13)^2/4, u_0 = alpha^h + alpha^-h = 2x + y, u_i = u_(i-1)^2 - 2),
# and its prime 778965587811*2^36627-1.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
  cd "$BATS_TEST_TMPDIR"
}

# w = (1 + sqrt 13)/2 (quadgen(13)); alpha = (3 + sqrt 13)^2/4 = 4 + 3w, of
# norm 1, so alpha^-h is the conjugate of alpha^h = x + yw and their sum is
# 2x + y. The residue u_(n-2) as riesel's res64: 16 hex digits.
GP_PAPER='w = quadgen(13);
if(w^2 != w + 3 || (3 + (2*w - 1))^2/4 != 4 + 3*w || norm(4 + 3*w) != 1, error("alpha"));
paper_u(h, n) = { my(N = h*2^n - 1, p = (Mod(1, N)*(4 + 3*w))^h, u = 2*real(p) + imag(p));
  for(i = 1, n - 2, u = u^2 - 2); lift(u) };
no_small_factor(N) = { forprime(p = 3, 997, if(N % p == 0 && N != p, return(0))); 1 };'

@test "--start d13 is the paper's D = 13 test: verdicts and res64 equal the quadratic-integer computation" {
  { echo "$GP_PAPER"; cat <<'GP'
{
setrand(13);
found = 0;
while(found < 40,
  h = 2*random(2^20) + 1; n = 100 + random(300); N = h*2^n - 1;
  if(kronecker(13, N) == -1 && no_small_factor(N),
    found++; u = paper_u(h, n);
    print(h, "*2^", n, "-1 ", if(u == 0, "prime", Strprintf("composite %016X", u % 2^64)))));
\\ Primes too: the test says prime iff u_(n-2) = 0.
found = 0;
while(found < 8,
  h = 2*random(2^20) + 1; n = 100 + random(200); N = h*2^n - 1;
  if(kronecker(13, N) == -1 && no_small_factor(N) && ispseudoprime(N),
    found++; print(h, "*2^", n, "-1 ", if(paper_u(h, n) == 0, "prime", "composite ?"))));
}
GP
  } | gp -q -f > want.txt
  [ "$(wc -l < want.txt)" -eq 48 ]
  cut -d' ' -f1 want.txt | riesel -j 2 --start d13 > got.jsonl
  paste -d' ' <(cut -d' ' -f1 want.txt) <(json-field verdict < got.jsonl) <(json-field res64 < got.jsonl) | sed 's/ $//' > got.txt
  run diff want.txt got.txt
  assert_success
  [ "$(grep -c ' prime$' want.txt)" -ge 8 ]
  run bash -c "json-field P < got.jsonl | sort -u"
  assert_output "11"
}

@test "778965587811*2^36627-1, the paper's prime, is prime by the D = 13 test" {
  run gp -q <<< 'print(kronecker(13, 778965587811*2^36627 - 1), " ", 778965587811 % 2, " ", 778965587811 < 2^36627)'
  assert_output "-1 1 1"
  run riesel --start d13 <<< '778965587811*2^36627-1'
  assert_success
  assert_output --regexp '"verdict":"prime","test":"llr","P":11,'
}
