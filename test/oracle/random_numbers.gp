\\ Writes COUNT test numbers with PARI's verdicts, one "number verdict" per
\\ line: proved verdicts (isprime) below 2^64, BPSW (ispseudoprime) above.
\\ Sizes are spread log-uniformly over 2..3000 bits; the mix holds random
\\ integers, random primes, semiprimes without small factors, and
\\ k*2^n+-1 numbers written as expressions.
\\ Usage: gp -q -f -D datadir=... with COUNT and SEED set before reading.
verdict(n) = if(n < 2^64, if(isprime(n), "prime", "composite"), if(ispseudoprime(n), "probable-prime", "composite"));
bits_between(lo, hi) = floor(exp(log(lo) + (log(hi) - log(lo)) * random(1.)));
random_bits(b) = if(b < 2, 2 + random(2), 2^(b-1) + random(2^(b-1)));
{
  setrand(SEED);
  for (i = 1, COUNT,
    kind = random(100);
    if (kind < 65,
      n = random_bits(bits_between(2, 3000)); print(n, " ", verdict(n)),
    kind < 85,
      b = bits_between(3, 700); n = randomprime([2^(b-1), 2^b - 1]); print(n, " ", verdict(n)),
    kind < 95,
      b = bits_between(8, 400); p = randomprime([2^(b-1), 2^b - 1]); q = randomprime([2^(b-1), 2^b - 1]);
      n = p * q; print(n, " ", verdict(n)),
      k = 2 * random(2^20) + 1; e = 64 + random(1500); c = if(random(2), 1, -1);
      n = k * 2^e + c; print(k, "*2^", e, if(c > 0, "+1", "-1"), " ", verdict(n)));
  );
}
