\\ Writes form records {"k","n","form"[,"length"]} with PARI's verdict for the
\\ whole form (all members must be prime): "record<TAB>verdict" per line.
verdict(N) = if(N < 2^64, if(isprime(N), 2, 0), if(ispseudoprime(N), 1, 0));
name(v) = if(v == 2, "prime", if(v == 1, "probable-prime", "composite"));
members(k, n, form, len) = {
  if(form == "twin", [k*2^n-1, k*2^n+1],
  form == "sg", [k*2^n-1, k*2^(n+1)-1],
  form == "cc1", vector(len, i, k*2^(n+i-1)-1),
  form == "cc2", vector(len, i, k*2^(n+i-1)+1),
  form == "riesel", [k*2^n-1],
  [k*2^n+1]);
}
{
  forstep(k = 1, 61, 2,
    foreach([2, 3, 5, 8, 13, 21, 34, 55, 63, 64, 65, 89, 144], n,
      foreach(["twin", "sg", "riesel", "proth"], form,
        v = vecmin(apply(verdict, members(k, n, form, 0)));
        print("{\"k\":", k, ",\"n\":", n, ",\"form\":\"", form, "\"}\t", name(v)));
      foreach(["cc1", "cc2"], form,
        v = vecmin(apply(verdict, members(k, n, form, 3)));
        print("{\"k\":", k, ",\"n\":", n, ",\"form\":\"", form, "\",\"length\":3}\t", name(v)))));
}
