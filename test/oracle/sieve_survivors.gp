\\ sieve_survivors.gp: brute-force oracle for `sieve twin|sg|cc1|cc2|riesel|proth`.
\\ Prints the surviving k, one per line, in increasing order. Shares nothing
\\ with the tool's sieve: every member N of every candidate is tested on its
\\ own, by a gcd with the product of all the sieving primes.
\\
\\ Rule: a candidate is removed iff one of its members N has a prime factor
\\ p <= PMAX with p < N. So N = 1 never removes, and neither does a prime
\\ N <= PMAX (its only prime factor is N itself).
\\
\\ One case: set these before reading the file, e.g.
\\   { echo 'FORM="twin"; N=5; KMIN=1; KMAX=3000; PMAX=1000;'; cat sieve_survivors.gp; } | gp -q -f
\\   FORM  "twin", "sg", "cc1", "cc2", "riesel" or "proth"
\\   N     the exponent n;   LEN  chain length for cc1/cc2 (2 when unset)
\\   PMAX  the sieve bound, or a vector of prime ranges [[a, b], ...] to sieve
\\         with instead (for a --shard run: [[3, 2^20], [block low, block high]])
\\   KMIN, KMAX         a plain k range, or
\\   H0, C, XMIN, XMAX  k = H0 + C*x for XMIN <= x <= XMAX
\\ Many cases in one gp run: set CASES = [case, ...] instead, each case being
\\   [form, len, n, [kmin, kmax], pmax]  or  [form, len, n, [h0, c, xmin, xmax], pmax];
\\ each case's survivors are then preceded by a line "# case i".

default(debugmem, 0);
default(parisizemax, 2^30);  \\ the product of the primes up to 3e6 alone is 540 kB

\\ The members as [exponent offset, c]: member i is k*2^(n+offset)+c.
sieve_members(form, len) =
{
  if(form == "twin", return([[0, -1], [0, 1]]));
  if(form == "sg", return([[0, -1], [1, -1]]));
  if(form == "cc1", return(vector(len, i, [i - 1, -1])));
  if(form == "cc2", return(vector(len, i, [i - 1, 1])));
  if(form == "riesel", return([[0, -1]]));
  if(form == "proth", return([[0, 1]]));
  error("sieve_survivors.gp: unknown form ", form);
}

\\ The product of the sieving primes (the last one is kept: cases often share pmax).
sieve_primorial_of = 0; sieve_primorial_value = 1;
sieve_primorial(pmax) =
{
  if(pmax === sieve_primorial_of, return(sieve_primorial_value));
  sieve_primorial_of = pmax;
  sieve_primorial_value = if(type(pmax) == "t_INT", vecprod(primes([2, pmax])),
                             vecprod(vector(#pmax, i, vecprod(primes(pmax[i])))));
}

\\ Removed iff g = gcd(N, P) > 1 and N is not itself prime:
\\ then some sieving prime p divides N and p != N, so p < N.
member_removed(m, r) =
{
  my(g = gcd(m, r));
  g > 1 && !(g == m && isprime(m));
}

\\ The surviving k as a vector; kspec = [kmin, kmax] or [h0, c, xmin, xmax].
sieve_survivors(form, len, n, kspec, pmax) =
{
  my(ms = sieve_members(form, len), ks, P, chunk = 256, out = List());
  if(#kspec == 4,
    ks = vector(kspec[4] - kspec[3] + 1, i, kspec[1] + kspec[2]*(kspec[3] + i - 1)),
    ks = vector(kspec[2] - kspec[1] + 1, i, kspec[1] + i - 1));
  \\ gcd(N, P) = gcd(N, P mod M) whenever N divides M: P is reduced once modulo
  \\ the product of all members, then modulo each chunk's product.
  my(all = vecprod(vector(#ks, i, vecprod(vector(#ms, j, ks[i]*2^(n + ms[j][1]) + ms[j][2])))));
  P = sieve_primorial(pmax) % all;
  forstep(start = 1, #ks, chunk,
    my(part = ks[start .. min(start + chunk - 1, #ks)], vals, R);
    vals = vector(#part * #ms, j, my(k = part[(j - 1) \ #ms + 1], e = ms[(j - 1) % #ms + 1]); k*2^(n + e[1]) + e[2]);
    R = P % vecprod(vals);
    for(i = 1, #part,
      my(dead = 0);
      for(j = 1, #ms, if(member_removed(vals[(i - 1)*#ms + j], R), dead = 1; break));
      if(!dead, listput(out, part[i]))));
  Vec(out);
}

{
  if(type(CASES) == "t_VEC",
    for(i = 1, #CASES,
      my(c = CASES[i]);
      print("# case ", i);
      foreach(sieve_survivors(c[1], c[2], c[3], c[4], c[5]), k, print(k))),
    my(kspec = if(type(H0) == "t_INT", [H0, C, XMIN, XMAX], [KMIN, KMAX]));
    foreach(sieve_survivors(FORM, if(type(LEN) == "t_INT", LEN, 2), N, kspec, PMAX), k, print(k)));
}
