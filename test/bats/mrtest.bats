#!/usr/bin/env bats
# Command-line behaviour of mrtest: formats, options, errors, pipelines.
# Verdicts are checked against published facts (Mersenne exponents, the
# seed paper's numbers); the PARI/GP comparisons live in mrtest_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

@test "--help prints usage on stdout and exits 0" {
  run mrtest --help
  assert_success
  assert_output --partial "Usage: mrtest"
  assert_output --partial "--keep"
}

@test "--version names the tool" {
  run mrtest --version
  assert_success
  assert_output --regexp '^mrtest \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
}

@test "an unknown option is a usage error with exit 2" {
  run mrtest --no-such-option
  assert_failure 2
  assert_output --partial "Try 'mrtest --help' for more information."
}

@test "conflicting options are a usage error with exit 2" {
  run mrtest --test lucas --bases 3 <<< "97"
  assert_failure 2
  assert_output --partial "--bases and --rounds go with"
}

@test "plain numbers, hex and expressions get verdicts" {
  run bash -c 'printf "97\n100\n0x61\n2^61-1\n(2^89-1)*3\n" | mrtest | python3 -c "
import json,sys
for l in sys.stdin:
    r=json.loads(l); print(r[\"verdict\"], r.get(\"witness\",\"-\"))"'
  assert_success
  assert_output "prime -
composite factor 2
prime -
prime -
composite factor 3"
}

@test "Mersenne numbers 2^p-1 for p < 1300 match the published exponents" {
  for p in $(seq 2 1300); do echo "2^$p-1"; done > mersenne.txt
  run bash -c "mrtest -j 2 mersenne.txt | grep -v '\"composite\"' | python3 -c '
import json,sys
print(\" \".join(str(json.loads(l)[\"n\"]) for l in sys.stdin))'"
  assert_success
  assert_output "2 3 5 7 13 17 19 31 61 89 107 127 521 607 1279"
}

@test "the seed paper: 778965587811*2^36627-1 is prime, 778965587811*2^36629-1 is not" {
  run bash -c "printf '778965587811*2^36627-1\n778965587811*2^36629-1\n' | mrtest -j 2 | json-field verdict"
  assert_success
  assert_output "probable-prime
composite"
}

@test "records keep their other fields, and the tool's fields come last in a fixed order" {
  run bash -c "echo '{\"id\":\"x7\",\"number\":\"101\",\"note\":[1,2]}' | mrtest | sed 's/\"seconds\":[0-9.e-]*/\"seconds\":S/'"
  assert_success
  assert_output '{"id":"x7","number":"101","note":[1,2],"verdict":"prime","test":"bpsw","seconds":S}'
}

@test "kbnc records with k as a string above 2^53" {
  run bash -c "echo '{\"k\":\"12345678901234567891\",\"b\":2,\"n\":200,\"c\":1}' | mrtest | json-field k"
  assert_success
  assert_output "12345678901234567891"
}

@test "CSV in, CSV out with a header and the tool's columns" {
  printf 'id,number\na,13\nb,"15"\n' > in.csv
  run bash -c "mrtest --csv in.csv | cut -d, -f1-5"
  assert_success
  assert_output "id,number,verdict,test,witness
a,13,prime,bpsw,
b,15,composite,bpsw,factor 3"
}

@test "forms test every member and stop at the first composite" {
  # 3*2^1 +- 1 = 5, 7 (twins); 5*2^1 -+ 1 = 9 (composite), so the second stops early.
  run bash -c "printf '{\"k\":3,\"n\":1,\"form\":\"twin\"}\n{\"k\":5,\"n\":1,\"form\":\"twin\"}\n' | mrtest | json-field members"
  assert_success
  assert_line --index 0 '[{"n": 1, "c": -1, "verdict": "prime"}, {"n": 1, "c": 1, "verdict": "prime"}]'
  assert_line --index 1 '[{"n": 1, "c": -1, "verdict": "composite", "witness": "factor 3"}]'
}

@test "--keep passes on only the chosen verdicts" {
  run bash -c "seq 1 30 | mrtest --keep prime | json-field number | tr '\n' ' '"
  assert_success
  assert_output "2 3 5 7 11 13 17 19 23 29 "
}

@test "-j 4 keeps input order and gives the same verdicts as -j 1" {
  seq 100000000000 100000002000 > nums.txt
  mrtest -j 1 nums.txt | json-field verdict > one.txt
  mrtest -j 4 nums.txt | json-field verdict > four.txt
  run cmp one.txt four.txt
  assert_success
  [ "$(wc -l < four.txt)" -eq 2001 ]
}

@test "Fermat is fooled by a Carmichael number, Miller-Rabin and BPSW are not" {
  run bash -c "echo 561 | mrtest --test fermat --trial-bound 0 | json-field verdict"
  assert_output "probable-prime"
  run bash -c "echo 561 | mrtest --test mr --trial-bound 0 | json-field witness"
  assert_output "base 2"
  run bash -c "echo 561 | mrtest | json-field verdict"
  assert_output "composite"
}

# Theorem 2.3 of "Prime Hunting"; PARI/GP's comparisons are in mrtest_paper_oracle.bats.
@test "--test mr-grh: prime-if-grh above 19, prime up to 19, perfect powers named, --keep selects, --bases refused" {
  # 10^12+39 is prime (the first prime above 10^12); 1194649 = 1093^2 is a
  # strong pseudoprime to base 2; 561 = 3*11*17 is Carmichael's first.
  run bash -c "printf '17\n1000000000039\n1194649\n561\n' | mrtest -t mr-grh --trial-bound 0 | sed -E 's/.*\"verdict\":\"([a-z-]+)\",\"test\":\"([a-z-]+)\"(,\"witness\":\"([^\"]*)\")?.*/\\1 \\2 \\4/'"
  assert_success
  assert_line --index 0 "prime mr-grh "
  assert_line --index 1 "prime-if-grh mr-grh "
  assert_line --index 2 "composite mr-grh perfect power"
  assert_line --index 3 "composite mr-grh base 2"
  run bash -c "printf '1000000000039\n1000000000061\n1000000000041\n' | mrtest -t mr-grh --keep prime-if-grh | wc -l"
  assert_output "2"
  run mrtest -t mr-grh --bases 3 <<< "97"
  assert_failure 2
  # A form takes its weakest member: the Sophie Germain pair 11, 23 is
  # prime-if-grh (11 is prime: every base up to 9 was tried; 23 is not).
  run bash -c "echo '{\"k\":3,\"n\":2,\"form\":\"sg\"}' | mrtest -t mr-grh --trial-bound 0"
  assert_output --partial '"verdict":"prime-if-grh","test":"mr-grh"'
  assert_output --partial '"members":[{"n":2,"c":-1,"verdict":"prime"},{"n":3,"c":-1,"verdict":"prime-if-grh"}]'
}

@test "random bases are reproducible with --seed" {
  seq 1000001 2 1000401 > odd.txt
  run bash -c "mrtest -t mr -r 3 --seed 9 odd.txt | json-field witness | md5sum; mrtest -t mr -r 3 --seed 9 -j 2 odd.txt | json-field witness | md5sum"
  assert_success
  [ "${lines[0]}" = "${lines[1]}" ]
}

@test "a malformed line stops with file:line, exit 1, after the records before it" {
  printf '7\n11\n12+\n13\n' > bad.txt
  run mrtest bad.txt
  assert_failure 1
  assert_line --index 0 --partial '"number":"7"'
  assert_line --index 1 --partial '"number":"11"'
  assert_line --index 2 --regexp "^mrtest: bad.txt:3: missing number at column 4"
  [ "${#lines[@]}" -eq 3 ]
}

@test "--skip-bad reports bad lines and goes on" {
  printf '7\n12+\n13\n' > bad.txt
  run mrtest --skip-bad bad.txt
  assert_success
  assert_output --partial "mrtest: bad.txt:2:"
  assert_output --partial '"number":"13"'
  assert_output --partial "skipped 1 bad record"
}

@test "bad JSON records name the line" {
  printf '{"number":"7"}\n{"number": NaN}\n' > bad.jsonl
  run mrtest bad.jsonl
  assert_failure 1
  assert_output --partial "mrtest: bad.jsonl:2: invalid json"
  printf '{"k":1e400,"n":3,"c":1}\n' > huge.jsonl
  run mrtest huge.jsonl
  assert_failure 1
  assert_output --partial "huge.jsonl:1:"
}

@test "empty input gives no output and exit 0" {
  run mrtest < /dev/null
  assert_success
  assert_output ""
}

@test "binary garbage is an error, not a crash" {
  head -c 4096 /dev/urandom > garbage.bin
  printf '\0\1\2\n' >> garbage.bin
  run mrtest garbage.bin
  assert_failure 1
  assert_output --regexp "^mrtest: garbage.bin:[0-9]+: "
}

@test "huge, negative and zero numbers" {
  run mrtest <<< "2^99999999999"
  assert_failure 1
  assert_output --partial "more than --max-bits"
  run bash -c "printf -- '-7\n0\n1\n2\n' | mrtest | json-field verdict | tr '\n' ' '"
  assert_output "composite composite composite prime "
  run mrtest --max-bits 100 <<< "2^101+1"
  assert_failure 1
}

@test "a missing file is reported with its name" {
  run mrtest no-such-file.txt
  assert_failure 1
  assert_output "mrtest: no-such-file.txt: cannot open: No such file or directory"
}

@test "write errors on stdout are reported" {
  run bash -c "echo 97 | mrtest > /dev/full"
  assert_failure 1
  assert_output --partial "write error"
}

@test "a closed pipe ends mrtest quietly" {
  run bash -c "seq 1 2000000 | mrtest | head -n 1 > /dev/null; echo \"\${PIPESTATUS[1]}\""
  assert_output --regexp '^(0|141)$'
}

@test "--progress keeps stdout data only" {
  skip_volume_when_sanitized
  seq 1 200000 > many.txt
  mrtest --progress many.txt 2> err.txt > out.jsonl
  [ "$(wc -l < out.jsonl)" -eq 200000 ]
  run grep -vc '^{' out.jsonl
  assert_output "0"
}

@test "list options do not swallow the file that follows" {
  echo 97 > one.txt
  run bash -c "mrtest -k prime,composite -t mr -b 2,3 one.txt | json-field verdict"
  assert_success
  assert_output "prime"
}

@test "NewPGen and ABC files map onto the shared records" {
  printf '1000000:T:0:2:3\n3 1\n5 4\n' > twin.npg
  run bash -c "mrtest twin.npg | cut -d, -f1-3"
  assert_success
  assert_line --index 0 '{"k":3,"n":1,"form":"twin"'
  printf 'ABC $a*2^$b-1 // sieved to 1e6\n3 2\n3 3\n' > riesel.abc
  run bash -c "mrtest riesel.abc | cut -d, -f1-4"
  assert_line --index 0 '{"k":3,"b":2,"n":2,"c":-1'
  run bash -c "printf 'ABC \$a*2^\$b-1\n3 x\n' | mrtest"
  assert_failure 1
  assert_output --partial "mrtest: <stdin>:2:"
}

@test "fuzz seeds and regression inputs end with a verdict or a clean error" {
  shopt -s nullglob
  local inputs=() input
  for input in "$TOOLKIT_ROOT"/fuzz/seeds/*/* "$TOOLKIT_ROOT"/fuzz/regressions/*/*; do
    [ "$(basename "$input")" = README.md ] || inputs+=("$input")
  done
  [ "${#inputs[@]}" -gt 10 ]
  # All of them through one process, past each bad record: the sanitizer
  # pass runs only this (a sanitized process takes ~0.15 s to start).
  run --separate-stderr mrtest --skip-bad --max-bits 4096 "${inputs[@]}"
  [ "$status" -eq 0 ] || [ "$status" -eq 1 ] || { echo "exit $status: $stderr"; false; }
  [[ "$stderr" != *Sanitizer* && "$stderr" != *"runtime error"* ]] || { echo "$stderr"; false; }
  [ -n "${TOOLKIT_SANITIZED:-}" ] && return 0
  # Each on its own: a verdict, or exit 1 with mrtest's one-line message.
  for input in "${inputs[@]}"; do
    run mrtest --max-bits 4096 "$input"
    [ "$status" -eq 0 ] || [ "$status" -eq 1 ] || { echo "$input: exit $status"; false; }
    if [ "$status" -eq 1 ]; then
      [[ "${lines[-1]}" == "mrtest: "* ]] || { echo "$input: ${lines[-1]}"; false; }
    fi
  done
}

@test "a UTF-8 byte-order mark does not hide JSON input" {
  run bash -c "printf '\xef\xbb\xbf{\"number\":\"7\"}\n' | mrtest | json-field verdict"
  assert_output "prime"
}

@test "--skip-bad gets past over-long lines and read errors, and fails for unreadable files" {
  run bash -c "(head -c 70000000 /dev/zero | tr '\0' 1; echo; echo 7) | mrtest --skip-bad 2>/dev/null | json-field number"
  assert_success
  assert_output "7"
  run timeout 20 mrtest --skip-bad < /
  assert_failure 1
  assert_output --partial "read error"
  echo 7 > one.txt
  run mrtest --skip-bad one.txt missing.txt
  assert_failure 1
  assert_output --partial '"number":"7"'
  assert_output --partial "mrtest: missing.txt: cannot open"
  assert_output --partial "1 input file was not read"
}
