\\ sieve_factors.gp: what `sieve ... --factors FILE` should contain, worked out
\\ prime by prime in PARI/GP: for every removed candidate, the line
\\ "p | k*2^e+c" with p the smallest prime <= PMAX dividing one of its
\\ members (and smaller than that member), and the first such member.
\\ Lines come in increasing k (the tool's file is compared after sorting).
\\
\\ Variables, set before reading the file (as for sieve_survivors.gp):
\\   FORM, N, PMAX, LEN (cc1/cc2, default 2), and KMIN, KMAX or H0, C, XMIN, XMAX.
\\ Members k*2^(N+i)+c: k = -c/2^(N+i) (mod p) for p not dividing the step.

default(debugmem, 0);
default(parisizemax, 2^30);
if(type(LEN) != "t_INT", LEN = 2);

sieve_members(form) =
{
  if(form == "twin", return([[0, -1], [0, 1]]));
  if(form == "sg", return([[0, -1], [1, -1]]));
  if(form == "cc1", return(vector(LEN, i, [i - 1, -1])));
  if(form == "cc2", return(vector(LEN, i, [i - 1, 1])));
  if(form == "riesel", return([[0, -1]]));
  if(form == "proth", return([[0, 1]]));
  error("sieve_factors.gp: unknown FORM ", form);
}

sieve_factor_lines() =
{
  my(ms = sieve_members(FORM), h, step, x0, count, first, which, d);
  if(type(H0) == "t_INT", h = H0; step = C; x0 = XMIN; count = XMAX - XMIN + 1,
                          h = KMIN; step = 1; x0 = 0; count = KMAX - KMIN + 1);
  \\ Candidate i (1-based) is k = h + step*(x0 + i - 1).
  first = vector(count); which = vector(count);
  forprime(p = 3, PMAX,
    my(t = Mod(2, p)^-N);  \\ 2^-N; member j needs 2^-(N + offset)
    for(j = 1, #ms,
      my(e = N + ms[j][1], c = ms[j][2], target = -c * t / Mod(2, p)^ms[j][1], start);
      \\ Solve h + step*(x0 + i - 1) = target (mod p) for i.
      if(step % p == 0,
        if(Mod(h, p) != target, next);
        start = 1; d = 1,
        start = lift((target - h) / Mod(step, p) - x0) + 1; d = p);
      forstep(i = start, count, d,
        if(first[i], next);
        my(k = h + step*(x0 + i - 1));
        if(k*2^e + c == p, next);  \\ the member is p itself
        first[i] = p; which[i] = j)));
  for(i = 1, count, if(first[i],
    my(k = h + step*(x0 + i - 1), m = ms[which[i]]);
    print(first[i], " | ", k, "*2^", N + m[1], if(m[2] < 0, "-1", "+1"))));
}

sieve_factor_lines();
