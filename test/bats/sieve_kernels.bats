#!/usr/bin/env bats
# The scalar, AVX2 and AVX-512 kernels for 2^-n mod p must agree; the widest
# one the processor has is the default, TOOLKIT_SIEVE_KERNEL picks another.
# A kernel the processor lacks falls back to a narrower one, so every run is
# valid on any machine. Primes below and above 2^32 both go through.

load test_helper

@test "kernels agree: twin, large n, primes past 2^32" {
  for form in "twin --n 171960" "cc1 --length 3 --n 4099" "proth --n 65537"; do
    # shellcheck disable=SC2086
    ref=$(TOOLKIT_SIEVE_KERNEL=scalar sieve $form --k 1:3000 --pmax 2e6 --newpgen)
    for kernel in avx2 avx512; do
      # shellcheck disable=SC2086
      run env TOOLKIT_SIEVE_KERNEL=$kernel sieve $form --k 1:3000 --pmax 2e6 --newpgen
      assert_success
      [ "$output" = "$ref" ]
    done
  done
  # Sieving to 2^32 takes ~20 s of CPU per run under the sanitizers: the
  # release pass runs it.
  if sanitized; then return; fi
  big_ref=$(TOOLKIT_SIEVE_KERNEL=scalar sieve riesel --n 1000 --k 1:10 --pmax 4294967296)
  run sieve riesel --n 1000 --k 1:10 --pmax 4294967296
  assert_success
  [ "$output" = "$big_ref" ]
}

@test "kernels agree with the seed's parametrisation (inverse of c)" {
  ref=$(TOOLKIT_SIEVE_KERNEL=scalar sieve sg --n 5003 --h0 3 --c 2310 --x 1:20000 --pmax 3e6)
  run sieve sg --n 5003 --h0 3 --c 2310 --x 1:20000 --pmax 3e6
  assert_success
  [ "$output" = "$ref" ]
  [ -n "$ref" ]
}
