\\ Independent Lucas-Lehmer-Riesel and Proth residues for riesel's "P", "a"
\\ and "res64" fields (test/bats/riesel_oracle.bats); plain PARI, nothing
\\ shared with the library.
\\
\\ LLR: N = k*2^n-1 (k odd, k < 2^n, n >= 3) is prime iff u_(n-2) = 0 mod N,
\\ u_0 = V_k(P) mod N, u_i = u_(i-1)^2 - 2, where V is the Lucas sequence
\\ V_0 = 2, V_1 = P, V_(m+1) = P*V_m - V_(m-1). Here V_k comes from the
\\ matrix power [V_(k+1); V_k] = [P, -1; 1, 0]^k * [P; 2] (mod N), which for
\\ small k equals 2*T_k(P/2) (polchebyshev); res64 is the low 64 bits of
\\ u_(n-2) reduced into [0, N).
\\ Proth: N = k*2^n+1 is prime iff a^((N-1)/2) = -1 mod N for an a with
\\ (a/N) = -1; res64 is the low 64 bits of a^((N-1)/2) mod N.

\\ LLR's P: 4 when 3 does not divide k, else Rodseth's first P >= 3 with
\\ (P-2 / N) = 1 and (P+2 / N) = -1.
llr_P(k, n) = {
  my(N = k*2^n - 1);
  if (k % 3, return(4));
  for (P = 3, 1000, if (kronecker(P - 2, N) == 1 && kronecker(P + 2, N) == -1, return(P)));
  error("no P for ", k, "*2^", n, "-1");
}

llr_residue(k, n, P) = {
  my(N = k*2^n - 1, M = Mod([P, -1; 1, 0], N), u = (M^k * [P; 2])[2, 1]);
  for (i = 1, n - 2, u = u^2 - 2);
  lift(u);
}

\\ The first a >= 3 with (a / N) = -1.
proth_a(k, n) = {
  my(N = k*2^n + 1);
  for (a = 3, 1000, if (kronecker(a, N) == -1, return(a)));
  error("no a for ", k, "*2^", n, "+1");
}

proth_residue(k, n, a) = lift(Mod(a, k*2^n + 1)^(k*2^(n-1)));

\\ 16 upper-case hex digits, as riesel writes res64.
hex64(x) = Strprintf("%016X", x % 2^64);

\\ No prime factor below 1000 (riesel's trial division would answer first).
no_small_factor(N) = {
  forprime (p = 3, 997, if (N % p == 0 && N != p, return(0)));
  1;
}
