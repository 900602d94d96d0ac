#!/usr/bin/env bats
# Slow tests, outside the default suite (`make test-slow`, about 3 minutes
# on two cores): the record primes of Járai, Farkas, Csajbók, Kasza and
# Kovács that the seed ("Prime Hunting") reports, proved from their
# published forms. The expected verdicts come from the publications (the
# Prime Pages list the twins, the Sophie Germain pair and the chain), not
# from this tool:
#   16869987339975*2^171960 +- 1         twin primes (51,779 digits, 2005)
#   137211941292195*2^171960 - 1, *2^171961 - 1   Sophie Germain pair (2006)
#   1128330746865*2^66439 - 1, 66440, 66441       Cunningham chain of the
#                                                 first kind, length 3 (2008)
# A composite neighbour of each is checked as well, with its res64 from
# the FFT and from GMP alone, which must agree.

bats_require_minimum_version 1.5.0
load '../bats/test_helper'

setup() {
  cd "$BATS_TEST_TMPDIR"
}

@test "the twin primes 16869987339975*2^171960 +- 1 are proved prime (LLR and Proth)" {
  run --separate-stderr bash -c "echo '{\"k\":16869987339975,\"n\":171960,\"form\":\"twin\"}' | riesel --state st"
  assert_success
  run json-field verdict <<< "$output"
  assert_output "prime"
  run cut -d' ' -f1-3 st/lresults.txt
  assert_output "16869987339975*2^171960-1 is prime!
16869987339975*2^171960+1 is prime!"
}

@test "the Sophie Germain pair 137211941292195*2^171960-1, *2^171961-1 is proved prime" {
  run --separate-stderr bash -c "echo '{\"k\":137211941292195,\"n\":171960,\"form\":\"sg\"}' | riesel | json-field members"
  assert_success
  assert_output --regexp '^\[\{"n": 171960, "c": -1, "verdict": "prime", "test": "llr".*\}, \{"n": 171961, "c": -1, "verdict": "prime", "test": "llr".*\}\]$'
}

@test "the Cunningham chain 1128330746865*2^66439/66440/66441 - 1 is proved prime" {
  run --separate-stderr bash -c "echo '{\"k\":1128330746865,\"n\":66439,\"form\":\"cc1\",\"length\":3}' | riesel | json-field verdict"
  assert_success
  assert_output "prime"
}

@test "composite neighbours have the same res64 from the FFT and from GMP alone" {
  # The record chain has length 3, so its neighbours below and above are
  # composite (the Prime Pages would list a longer chain).
  printf '1128330746865*2^66442-1\n1128330746865*2^66438-1\n' > near.txt
  run --separate-stderr bash -c "riesel -j 2 --arithmetic fft near.txt | sed 's/,\"seconds\":[^,}]*//'"
  assert_success
  fft_output=$output
  run --separate-stderr bash -c "riesel -j 2 --arithmetic gmp near.txt | sed 's/,\"seconds\":[^,}]*//'"
  assert_success
  [ "$output" = "$fft_output" ]
  run json-field verdict <<< "$fft_output"
  assert_output "composite
composite"
  # The first has the factor 11; the second is settled by LLR, with a res64.
  run json-field res64 <<< "$fft_output"
  assert_line --index 1 --regexp '^[0-9A-F]{16}$'
}
