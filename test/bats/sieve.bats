#!/usr/bin/env bats
# Command-line behaviour of sieve: output formats, threads, shards and merge,
# checkpoints and signals, errors, and the pipeline into mrtest. Expected
# outputs come from hand derivations or PARI/GP one-liners, never from the
# tool itself; the brute-force comparisons live in sieve_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

# A run long enough to interrupt (about 1 s here, 3-5 s under ASan) but with a
# small factors file: 2*10^4 candidates, primes up to 4*10^8.
LONG="twin --n 1000 --k 1:2e4 --pmax 4e8"

# Shards only differ above 2^20; 5*10^7 keeps the runs short.
SHARDED="twin --n 1000 --k 1:3000 --pmax 5e7"

# long_reference: the uninterrupted $LONG run, computed once per file:
# $BATS_FILE_TMPDIR/long.txt and long.factors.
long_reference() {
  if [ ! -s "$BATS_FILE_TMPDIR/long.factors" ]; then
    sieve $LONG --factors "$BATS_FILE_TMPDIR/long.factors" > "$BATS_FILE_TMPDIR/long.txt"
  fi
  cp "$BATS_FILE_TMPDIR/long.txt" want.txt
  cp "$BATS_FILE_TMPDIR/long.factors" want.factors
}


# gp_lines EXPR: runs a PARI/GP expression and prints its output.
gp_lines() {
  echo "$1" | gp -q -f
}

# differ FILE... -- REFERENCE: at least one FILE differs from REFERENCE
# (a bare '! cmp' would not fail a bats test).
differ() {
  local reference=${*: -1} file
  for file in "${@:1:$# - 2}"; do
    cmp -s "$file" "$reference" || return 0
  done
  echo "every file equals $reference"
  return 1
}

need_gp() {
  command -v gp >/dev/null || skip "PARI/GP (pari-gp) is not installed"
}

# ------------------------------------------------------------ help, version

@test "--help prints usage on stdout and exits 0" {
  run --separate-stderr sieve --help
  assert_success
  assert_output --partial "Usage: sieve"
  assert_output --partial "twin"
  assert_output --partial "merge"
  [ -z "$stderr" ]
  run sieve twin --help
  assert_success
  assert_output --partial "--pmax"
  assert_output --partial "--checkpoint"
  assert_output --partial "--shard"
  run sieve cc1 --help
  assert_success
  assert_output --partial "--length"
}

@test "--version names the tool" {
  run sieve --version
  assert_success
  assert_output --regexp '^sieve \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
}

@test "no subcommand, an unknown option or an unknown subcommand is a usage error with exit 2" {
  run sieve
  assert_failure 2
  assert_output --partial "Try 'sieve --help' for more information."
  run sieve twin --n 5 --k 1:10 --pmax 100 --no-such-option
  assert_failure 2
  assert_output --partial "Try 'sieve --help' for more information."
  run sieve sextuplets --n 5
  assert_failure 2
  assert_output --partial "Try 'sieve --help'"
}

# ------------------------------------------------------------ output formats

# Twins k*2 -+ 1 for k <= 20: the pairs (2k-1, 2k+1) are both prime for
# k = 2, 3, 6, 9, 15 (3,5  5,7  11,13  17,19  29,31), and k = 1 gives 1 and 3:
# 1 has no prime factor and 3 is a prime <= pmax, so neither removes k = 1.
# Every other k has a member 9, 15, 21, 25, 27, 33, 35 or 39 with a factor 3 or 5.
@test "JSON Lines: the twins k*2^1+-1 for k <= 20, by hand" {
  run --separate-stderr sieve twin --n 1 --k 1:20 --pmax 1000
  assert_success
  assert_output '{"k":1,"n":1,"form":"twin"}
{"k":2,"n":1,"form":"twin"}
{"k":3,"n":1,"form":"twin"}
{"k":6,"n":1,"form":"twin"}
{"k":9,"n":1,"form":"twin"}
{"k":15,"n":1,"form":"twin"}'
  [ -z "$stderr" ]
}

@test "CSV: a header row, then one row per survivor" {
  run sieve twin --n 1 --k 1:20 --pmax 1000 --csv
  assert_success
  assert_output 'k,n,form
1,1,twin
2,1,twin
3,1,twin
6,1,twin
9,1,twin
15,1,twin'
  # --csv is a global option: before the subcommand as well.
  run sieve --csv twin --n 1 --k 1:20 --pmax 1000
  assert_line --index 0 'k,n,form'
  # sieve(1): the header comes with the first record, so no survivors, no
  # output (4k+1, 8k+1, 16k+1 for k <= 12: one of them always has a factor 3, 5
  # or 7 below itself, e.g. 9, 25, 145 or 49).
  run --separate-stderr sieve cc2 --length 3 --n 2 --k 1:12 --pmax 1000 --csv
  assert_success
  assert_output ""
}

@test "NewPGen: 'pmax:T:0:2:3' then 'k n' lines for twins" {
  run sieve twin --n 1 --k 1:20 --pmax 1000 --newpgen
  assert_success
  assert_output '1000:T:0:2:3
1 1
2 1
3 1
6 1
9 1
15 1'
}

@test "ABC: one expression for both twins, then k lines" {
  run sieve twin --n 1 --k 1:20 --pmax 1000 --abc
  assert_success
  assert_output 'ABC $a*2^1+1 & $a*2^1-1 // Sieved to 1000
1
2
3
6
9
15'
}

@test "ABCD: the first k in brackets, then differences" {
  run sieve twin --n 1 --k 1:20 --pmax 1000 --abcd
  assert_success
  # 1, then 2-1, 3-2, 6-3, 9-6, 15-9.
  assert_output 'ABCD $a*2^1+1 & $a*2^1-1 [1] // Sieved to 1000
1
1
3
3
6'
  # No survivors, no first k, no output (sieve(1)).
  run --separate-stderr sieve cc2 --length 3 --n 2 --k 1:12 --pmax 1000 --abcd
  assert_success
  assert_output ""
  run sieve cc2 --length 3 --n 2 --k 1:12 --pmax 1000 --newpgen
  assert_output "1000:2:3:2:1045"
}

# For pmax >= sqrt(largest member), a candidate survives iff each member is
# prime (or 1): the expected lists below come from gp's isprime.
@test "Riesel k*2^2-1, k <= 12: NewPGen 'M:1:2:2', ABC with \$b, ABCD" {
  need_gp
  expected=$(gp_lines 'for(k = 1, 12, if(isprime(4*k - 1), print(k, " 2")))')
  [ "$(echo "$expected" | wc -l)" -eq 8 ]  # 3 7 11 19 23 31 43 47
  run sieve riesel --n 2 --k 1:12 --pmax 1000 --newpgen
  assert_success
  assert_output "1000:M:1:2:2
$expected"
  run sieve riesel --n 2 --k 1:12 --pmax 1000 --abc
  assert_success
  assert_output 'ABC $a*2^$b-1 // Sieved to 1000
'"$expected"
  run sieve riesel --n 2 --k 1:12 --pmax 1000 --abcd
  assert_success
  ks=$(echo "$expected" | cut -d' ' -f1)
  assert_output "ABCD \$a*2^2-1 [$(echo "$ks" | head -1)] // Sieved to 1000
$(echo "$ks" | awk 'NR > 1 { print $1 - prev } { prev = $1 }')"
}

@test "parametrised runs add x: twin k = 15 + 30x, x = 0..10, n = 3" {
  need_gp
  expected=$(gp_lines 'for(x = 0, 10, k = 15 + 30*x; if(isprime(8*k - 1) && isprime(8*k + 1), print("{\"k\":", k, ",\"n\":3,\"form\":\"twin\",\"x\":", x, "}")))')
  [ -n "$expected" ]
  run sieve twin --n 3 --h0 15 --c 30 --x 0:10 --pmax 1000
  assert_success
  assert_output "$expected"
  csv=$(gp_lines 'for(x = 0, 10, k = 15 + 30*x; if(isprime(8*k - 1) && isprime(8*k + 1), print(k, ",3,twin,", x)))')
  run sieve twin --n 3 --h0 15 --c 30 --x 0:10 --pmax 1000 --csv
  assert_success
  assert_output "k,n,form,x
$csv"
}

@test "chains add length: cc1 k*2^(2+i)-1, i < 3, for k <= 12" {
  need_gp
  expected=$(gp_lines 'for(k = 1, 12, if(isprime(4*k - 1) && isprime(8*k - 1) && isprime(16*k - 1), print("{\"k\":", k, ",\"n\":2,\"form\":\"cc1\",\"length\":3}")))')
  [ -n "$expected" ]
  run sieve cc1 --length 3 --n 2 --k 1:12 --pmax 1000
  assert_success
  assert_output "$expected"
  run sieve cc1 --length 3 --n 2 --k 1:12 --pmax 1000 --csv
  assert_line --index 0 'k,n,form,length'
}

@test "every form's NewPGen, ABC, ABCD and CSV headers" {
  # form arguments | NewPGen shape | ABC expression | ABCD expression
  row=0
  while IFS='|' read -r form shape abc abcd; do
    # Sanitized: every third row (twin, a chain of three, riesel).
    if sanitized && [ $((row++ % 3)) -ne 0 ]; then continue; fi
    run sieve $form --n 4 --k 1:2000 --pmax 1000 --newpgen
    assert_success
    assert_line --index 0 "1000:$shape"
    first=${lines[1]% 4}
    [[ "$first" =~ ^[0-9]+$ ]]
    run sieve $form --n 4 --k 1:2000 --pmax 1000 --abc
    assert_success
    assert_line --index 0 "ABC $abc // Sieved to 1000"
    run sieve $form --n 4 --k 1:2000 --pmax 1000 --abcd
    assert_success
    assert_line --index 0 "ABCD $abcd [$first] // Sieved to 1000"
    run sieve $form --n 4 --k 1:2000 --pmax 1000 --csv
    case $form in cc*) assert_line --index 0 'k,n,form,length' ;; *) assert_line --index 0 'k,n,form' ;; esac
  done <<'TABLE'
twin|T:0:2:3|$a*2^4+1 & $a*2^4-1|$a*2^4+1 & $a*2^4-1
sg|S:0:2:10|$a*2^4-1 & 2*($a*2^4-1)+1|$a*2^4-1 & 2*($a*2^4-1)+1
cc1 --length 2|S:0:2:10|$a*2^4-1 & $a*2^5-1|$a*2^4-1 & $a*2^5-1
cc1 --length 3|1:3:2:1066|$a*2^4-1 & $a*2^5-1 & $a*2^6-1|$a*2^4-1 & $a*2^5-1 & $a*2^6-1
cc2 --length 2|C:0:2:5|$a*2^4+1 & $a*2^5+1|$a*2^4+1 & $a*2^5+1
cc2 --length 3|2:3:2:1045|$a*2^4+1 & $a*2^5+1 & $a*2^6+1|$a*2^4+1 & $a*2^5+1 & $a*2^6+1
riesel|M:1:2:2|$a*2^$b-1|$a*2^4-1
proth|P:1:2:1|$a*2^$b+1|$a*2^4+1
TABLE
}

@test "all five formats list the same k, in increasing order" {
  skip_volume_when_sanitized
  for form in "sg" "cc2 --length 3" "proth"; do
    for range in "--k 1:30000" "--h0 1155 --c 2310 --x 0:3000"; do
      sieve $form --n 40 $range --pmax 1e5 | json-field k > json.txt
      [ "$(wc -l < json.txt)" -gt 5 ]
      sort -n -c json.txt
      sieve $form --n 40 $range --pmax 1e5 --csv | tail -n +2 | cut -d, -f1 > csv.txt
      sieve $form --n 40 $range --pmax 1e5 --newpgen | tail -n +2 | cut -d' ' -f1 > npg.txt
      sieve $form --n 40 $range --pmax 1e5 --abc | tail -n +2 | cut -d' ' -f1 > abc.txt
      sieve $form --n 40 $range --pmax 1e5 --abcd |
        awk 'NR == 1 { match($0, /\[[0-9]+\]/); k = substr($0, RSTART + 1, RLENGTH - 2); print k; next } { k += $1; print k }' > abcd.txt
      for f in csv npg abc abcd; do
        run cmp json.txt $f.txt
        assert_success
      done
    done
  done
}

@test "k at or above 2^53 is a JSON string, and plain digits elsewhere" {
  run sieve proth --n 2 --k 18446744073709551515:18446744073709551615 --pmax 1000
  assert_success
  assert_line --index 0 --regexp '^\{"k":"1844674407370955[0-9]{4}","n":2,"form":"proth"\}$'
  run sieve proth --n 2 --k 9007199254740992:9007199254741092 --pmax 1000 --newpgen
  assert_line --index 1 --regexp '^90071992547[0-9]{5} 2$'
}

# ------------------------------------------------------------ threads

@test "-j 1 and -j 2 (and -j 3) write byte-identical output in every format (pmax above 2^20)" {
  skip_volume_when_sanitized  # the factors/checkpoint test below runs -j 1 and -j 2 under the sanitizers
  # 2.5*10^6 candidates: two segments of the small-prime phase, 5 blocks of large primes.
  args="twin --n 1000 --k 1:2.5e6 --pmax 2e7"
  for format in "" --csv --newpgen --abc --abcd; do
    sieve $args $format -j 1 > one.txt
    sieve $args $format -j 2 > two.txt
    [ "$(wc -l < one.txt)" -gt 1000 ]
    run cmp one.txt two.txt
    assert_success
  done
  sieve -j 3 $args > three.txt
  sieve $args > one.txt
  run cmp one.txt three.txt
  assert_success
}

@test "-j 1 and -j 2 write the same factors file and the same final checkpoint" {
  args="cc1 --length 2 --n 1000 --k 1:2e5 --pmax 5e7"
  sieve $args -j 1 --factors one.txt --checkpoint one.ckpt > out1.txt
  sieve $args -j 2 --factors two.txt --checkpoint two.ckpt > out2.txt
  run cmp one.txt two.txt
  assert_success
  run cmp out1.txt out2.txt
  assert_success
  run cmp one.ckpt two.ckpt
  assert_success
  # Primes above 2^20 (the parallel blocks) did remove some candidates.
  [ "$(awk '$1 > 1048576' one.txt | wc -l)" -gt 10 ]
}

# ------------------------------------------------------------ shards and merge

@test "--shard 1/3, 2/3, 3/3 merged equal one run, byte for byte, in every format" {
  skip_volume_when_sanitized
  for format in "" --csv --newpgen --abc --abcd; do
    sieve $SHARDED $format > single.txt
    for i in 1 2 3; do sieve $SHARDED $format --shard $i/3 > shard$i.txt; done
    # The shards do differ: each keeps candidates another shard removes.
    differ shard1.txt shard2.txt shard3.txt -- single.txt
    run sieve merge shard1.txt shard2.txt shard3.txt
    assert_success
    sieve merge shard1.txt shard2.txt shard3.txt > merged.txt
    run cmp merged.txt single.txt
    assert_success
    # The order of the files does not matter.
    sieve merge shard3.txt shard1.txt shard2.txt > merged.txt
    run cmp merged.txt single.txt
    assert_success
  done
}

@test "shards of a parametrised sg run merge to the single run" {
  args="sg --n 500 --h0 1155 --c 2310 --x 0:5000 --pmax 1.3e7"
  sieve $args --newpgen > single.npg
  for i in 1 2; do sieve $args --newpgen --shard $i/2 > s$i.npg; done
  differ s1.npg s2.npg -- single.npg
  sieve merge s1.npg s2.npg > merged.npg
  run cmp merged.npg single.npg
  assert_success
}

@test "shards run through GNU parallel merge to the single run" {
  skip_volume_when_sanitized  # the merge itself runs sanitized in the tests above and below
  command -v parallel >/dev/null || skip "GNU parallel is not installed"
  dir=$BATS_TEST_TMPDIR
  parallel --will-cite sieve $SHARDED --newpgen --shard {}/3 '>' "$dir"/s{}.npg ::: 1 2 3 < /dev/null
  parallel --will-cite sieve $SHARDED --abcd --shard {}/3 '>' "$dir"/s{}.abcd ::: 1 2 3 < /dev/null
  sieve $SHARDED --newpgen > single.npg
  sieve $SHARDED --abcd > single.abcd
  sieve merge s1.npg s2.npg s3.npg > merged.npg
  sieve merge s1.abcd s2.abcd s3.abcd > merged.abcd
  run cmp merged.npg single.npg
  assert_success
  run cmp merged.abcd single.abcd
  assert_success
}

@test "merge keeps the smallest depth of the shards' headers" {
  sieve twin --n 1000 --k 1:3000 --pmax 5e7 --newpgen --shard 1/2 > a.npg
  sieve twin --n 1000 --k 1:3000 --pmax 3e7 --newpgen --shard 2/2 > b.npg
  run sieve merge a.npg b.npg
  assert_success
  assert_line --index 0 "30000000:T:0:2:3"
}

@test "merging outputs of different runs or formats is an error naming the file" {
  sieve twin --n 1000 --k 1:3000 --pmax 1e6 --newpgen --shard 1/2 > twin.npg
  sieve sg --n 1000 --k 1:3000 --pmax 1e6 --newpgen --shard 2/2 > sg.npg
  run sieve merge twin.npg sg.npg
  assert_failure 1
  assert_output --regexp "^sieve: sg.npg:[0-9]+: shard 2/2 of form=sg .*not shards of one run"
  sieve twin --n 1000 --k 1:3000 --pmax 1e6 --abc --shard 1/2 > n1000.abc
  sieve twin --n 1001 --k 1:3000 --pmax 1e6 --abc --shard 2/2 > n1001.abc
  run sieve merge n1000.abc n1001.abc
  assert_failure 1
  assert_output --partial "n1001.abc"
  sieve twin --n 1000 --k 1:3000 --pmax 1e6 --shard 2/2 > twin.jsonl
  run sieve merge twin.npg twin.jsonl
  assert_failure 1
  assert_output --partial "twin.jsonl"
  sieve twin --n 1000 --k 1:3000 --pmax 1e6 --csv --shard 1/2 > plain.csv
  sieve twin --n 1000 --h0 15 --c 30 --x 1:1000 --pmax 1e6 --csv --shard 2/2 > param.csv
  [ "$(wc -l < param.csv)" -gt 2 ]
  run sieve merge plain.csv param.csv
  assert_failure 1
  assert_output --partial "param.csv"
}

@test "merge: binary garbage, bad ABCD files, empty files and one run's output are errors" {
  head -c 4096 /dev/urandom > garbage.bin
  printf '\0\1\2\n' >> garbage.bin
  run sieve merge garbage.bin
  assert_failure 1
  assert_output --regexp "^sieve: garbage.bin(:[0-9]+)?: "
  sieve $SHARDED --newpgen --shard 1/2 > good.npg
  run sieve merge good.npg garbage.bin
  assert_failure 1
  assert_output --partial "garbage.bin"
  printf 'ABCD $a*2^5+1 [7] // Sieved to 1000\n4\nx\n' > bad.abcd
  run sieve merge bad.abcd
  assert_failure 1
  assert_output --partial "bad.abcd:3"
  # An empty file may be a shard killed before it wrote anything.
  : > empty1.txt
  : > empty2.txt
  run sieve merge empty1.txt empty2.txt
  assert_failure 1
  assert_output --regexp "^sieve: empty1.txt(:0)?: ends without the '// sieve shard"
  # One run (no --shard) writes no trailer: there is nothing to merge it with.
  sieve $SHARDED --newpgen > single.npg
  run sieve merge single.npg
  assert_failure 1
  assert_output --partial "single.npg"
  run sieve merge no-such-file.txt
  assert_failure 2
  assert_output --partial "no-such-file.txt"
}

@test "merge refuses a shard cut short, garbage, a damaged count, a duplicate or a missing shard, naming the file" {
  # The issue's case: a shard cut mid-line merged to a fraction of the survivors with exit 0.
  formats=("" --csv --newpgen --abc --abcd)
  if sanitized; then formats=("" --abcd); fi
  for format in "${formats[@]}"; do
    sieve $SHARDED $format > single.txt
    for i in 1 2 3; do sieve $SHARDED $format --shard $i/3 > s$i.txt; done
    size=$(wc -c < s2.txt)
    cuts=(1 $((size / 3)) $((size / 2)) $((size - 30)) $((size - 2)))
    if sanitized; then cuts=($((size / 2)) $((size - 2))); fi
    for cut in "${cuts[@]}"; do
      head -c "$cut" s2.txt > torn.txt
      run sieve merge s1.txt torn.txt s3.txt
      assert_failure 1
      assert_output --regexp "^sieve: torn.txt:[0-9]+: "
    done
    # Whole lines missing: the trailer's count tells.
    head -n 3 s2.txt > head.txt
    tail -n 1 s2.txt >> head.txt
    run sieve merge s1.txt head.txt s3.txt
    assert_failure 1
    assert_output --regexp "^sieve: head.txt:[0-9]+: holds [0-9]+ candidates where its last line says [0-9]+"
    echo hello > hello.txt
    run sieve merge s1.txt hello.txt s3.txt
    assert_failure 1
    assert_output --regexp "^sieve: hello.txt:1: ends without"
    run sieve merge s1.txt s2.txt s2.txt s3.txt
    assert_failure 1
    assert_output --regexp "^sieve: s2.txt:[0-9]+: shard 2/3 again"
    run sieve merge s1.txt s3.txt
    assert_failure 1
    assert_output --partial "shard 2/3 of form=twin length=1 n=1000 k=1:3000 missing"
    sieve merge s1.txt s2.txt s3.txt > merged.txt
    run cmp merged.txt single.txt
    assert_success
  done
}

@test "merge skips a UTF-8 byte-order mark at the start of a shard" {
  sieve $SHARDED --newpgen > single.npg
  for i in 1 2; do sieve $SHARDED --newpgen --shard $i/2 > s$i.npg; done
  printf '\357\273\277' | cat - s1.npg > bom.npg
  sieve merge bom.npg s2.npg > merged.npg
  run cmp merged.npg single.npg
  assert_success
}

@test "merge of shards where some shards keep nothing (JSON Lines, NewPGen, ABC, ABCD)" {
  # 1962*2^1000-1 has the factor 1696571 (> 2^20; PARI checks it), so k = 1962
  # survives the primes up to 2^20 and then only in the shards that lack it.
  # JSON Lines and ABCD shards without survivors are empty files.
  need_gp
  [ "$(gp_lines 'print((1962*2^1000 - 1) % 1696571)')" = 0 ]
  args="twin --n 1000 --k 1962:1962 --pmax 5e7"
  formats=("" --newpgen --abc --abcd)
  if sanitized; then formats=("" --abcd); fi
  for format in "${formats[@]}"; do
    for i in 1 2 3; do sieve $args $format --shard $i/3 > e$i.txt; done
    sieve $args $format > single.txt
    run sieve merge e1.txt e2.txt e3.txt
    assert_success
    sieve merge e1.txt e2.txt e3.txt > merged.txt
    run cmp merged.txt single.txt
    assert_success
  done
}

@test "merge of CSV shards whose intersection is empty writes what one run writes: nothing" {
  args="twin --n 1000 --k 1962:1962 --pmax 5e7 --csv"
  for i in 1 2 3; do sieve $args --shard $i/3 > e$i.csv; done
  sieve $args > single.csv
  [ ! -s single.csv ]  # sieve(1): the CSV header comes with the first record
  sieve merge e1.csv e2.csv e3.csv > merged.csv
  run cmp merged.csv single.csv
  assert_success
}

@test "merge names its missing argument SHARD" {
  run sieve merge
  assert_failure 2
  assert_output --partial "SHARD is required"
}

# ------------------------------------------------------------ checkpoints

@test "a run killed with -9 and resumed (with other -j) gives the same output and factors file" {
  long_reference
  sieve $LONG -j 1 --factors got.factors --checkpoint run.ckpt --checkpoint-every 0.05 > /dev/null 2>&1 3>&- &
  pid=$!
  wait_for run.ckpt
  kill -9 "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 137 ]  # it really was interrupted
  run --separate-stderr sieve $LONG -j 2 --factors got.factors --checkpoint run.ckpt --checkpoint-every 0.05 --resume
  assert_success
  [ -z "$stderr" ]
  echo "$output" > got.txt
  run cmp got.txt want.txt
  assert_success
  run cmp got.factors want.factors
  assert_success
  [ "$(wc -l < want.txt)" -gt 10 ]
}

@test "SIGINT and SIGTERM save a checkpoint and kill the process by that signal; --resume finishes the run" {
  long_reference
  for signal in INT TERM; do
    rm -f run.ckpt got.factors
    sieve $LONG --factors got.factors --checkpoint run.ckpt --checkpoint-every 0.05 > out.txt 2> err.txt 3>&- &
    pid=$!
    wait_for run.ckpt
    kill -"$signal" "$pid"
    status=0
    wait "$pid" || status=$?
    if [ "$signal" = INT ]; then [ "$status" -eq 130 ]; else [ "$status" -eq 143 ]; fi
    run cat err.txt
    assert_output --regexp "^sieve: stopped by signal [0-9]+ (after p = [0-9]+|while the primes up to 2\^20 sieved, after [0-9]+ of [0-9]+ segments); checkpoint saved"
    [ ! -s out.txt ]
    sieve $LONG --factors got.factors --checkpoint run.ckpt --resume > got.txt
    run cmp got.txt want.txt
    assert_success
    run cmp got.factors want.factors
    assert_success
  done
}

@test "SIGINT without --checkpoint says the work is lost and exits by the signal" {
  sieve twin --n 1000 --k 1:2e4 --pmax 1e11 --progress > out.txt 2> err.txt 3>&- &
  pid=$!
  wait_for_handler "$pid"
  kill -INT "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 130 ]
  run cat err.txt
  assert_output --regexp "no --checkpoint, so the work is lost"
  [ ! -s out.txt ]
}

@test "--resume without a checkpoint file warns and starts afresh; resuming a finished run repeats it" {
  args="twin --n 1000 --k 1:3000 --pmax 3e6"
  sieve $args --newpgen > want.npg
  run --separate-stderr sieve $args --newpgen --checkpoint new.ckpt --resume
  assert_success
  [[ "$stderr" == *"no checkpoint at new.ckpt"* ]]
  echo "$output" > got.npg
  run cmp got.npg want.npg
  assert_success
  [ -s new.ckpt ]
  run --separate-stderr sieve $args --newpgen --checkpoint new.ckpt --resume
  assert_success
  [ -z "$stderr" ]
  echo "$output" > again.npg
  run cmp again.npg want.npg
  assert_success
  # -q keeps the warning off stderr.
  run --separate-stderr sieve -q $args --newpgen --checkpoint other.ckpt --resume
  assert_success
  [ -z "$stderr" ]
}

@test "a run stopped by --min-rate resumes from its checkpoint to pmax: same output and factors as one run" {
  long_reference
  run --separate-stderr sieve $LONG --min-rate 1e12 --rate-window 0.1 --checkpoint run.ckpt --factors got.factors --newpgen
  assert_success
  [[ "$stderr" == *"--min-rate"* ]]
  [ "$(head -1 <<< "$output" | cut -d: -f1)" -lt 400000000 ]
  sieve $LONG --checkpoint run.ckpt --factors got.factors --resume > got.txt
  run cmp got.txt want.txt
  assert_success
  run cmp got.factors want.factors
  assert_success
}

@test "without --resume, --checkpoint starts afresh over any old file, and --factors is truncated" {
  args="twin --n 1000 --k 1:3000 --pmax 3e6"
  sieve $args --factors want.factors > want.txt
  sieve sg --n 7 --k 1:100 --pmax 1000 --checkpoint old.ckpt > /dev/null
  echo "not a factor line" > got.factors
  sieve $args --checkpoint old.ckpt --factors got.factors > got.txt
  run cmp got.txt want.txt
  assert_success
  run cmp got.factors want.factors
  assert_success
  # The checkpoint now belongs to this run.
  run sieve $args --checkpoint old.ckpt --resume
  assert_success
  assert_output "$(cat want.txt)"
}

@test "a damaged checkpoint is an error naming the file" {
  args="twin --n 1000 --k 1:3000 --pmax 3e6"
  sieve $args --checkpoint good.ckpt > /dev/null
  size=$(stat -c %s good.ckpt)
  # Truncated.
  head -c $((size - 5)) good.ckpt > short.ckpt
  run sieve $args --checkpoint short.ckpt --resume
  assert_failure 1
  assert_output --partial "short.ckpt"
  assert_output --partial "damaged"
  # One byte flipped in the middle.
  cp good.ckpt flipped.ckpt
  offset=$((size / 2))
  byte=$(od -An -tu1 -j "$offset" -N1 good.ckpt | tr -d ' ')
  printf "\\$(printf '%03o' $(( (byte + 1) % 256 )))" | dd of=flipped.ckpt bs=1 seek="$offset" conv=notrunc 2>/dev/null
  differ flipped.ckpt -- good.ckpt
  run sieve $args --checkpoint flipped.ckpt --resume
  assert_failure 1
  assert_output --partial "flipped.ckpt"
  # Empty, and not a checkpoint at all.
  : > empty.ckpt
  run sieve $args --checkpoint empty.ckpt --resume
  assert_failure 1
  assert_output --partial "empty.ckpt"
  echo "hello" > text.ckpt
  run sieve $args --checkpoint text.ckpt --resume
  assert_failure 1
  assert_output --partial "text.ckpt"
}

@test "a checkpoint written for other parameters is an error" {
  sieve twin --n 1000 --k 1:3000 --pmax 3e6 --checkpoint run.ckpt > /dev/null
  for other in "twin --n 1000 --k 1:3000 --pmax 4e6" "twin --n 1001 --k 1:3000 --pmax 3e6" \
               "sg --n 1000 --k 1:3000 --pmax 3e6" "twin --n 1000 --k 1:3001 --pmax 3e6" \
               "twin --n 1000 --k 1:3000 --pmax 3e6 --shard 1/2"; do
    run sieve $other --checkpoint run.ckpt --resume
    assert_failure 1
    assert_output --partial "run.ckpt"
    assert_output --partial "other parameters"
  done
}

@test "--resume needs --checkpoint; a factors file shorter than the checkpoint recorded is an error" {
  run sieve twin --n 1000 --k 1:3000 --pmax 3e6 --resume
  assert_failure 2
  assert_output --partial "--checkpoint"
  sieve twin --n 1000 --k 1:3000 --pmax 3e6 --checkpoint run.ckpt --factors f.txt > /dev/null
  [ -s f.txt ]
  : > f.txt
  run sieve twin --n 1000 --k 1:3000 --pmax 3e6 --checkpoint run.ckpt --factors f.txt --resume
  assert_failure 1
  assert_output --partial "f.txt"
}

# ------------------------------------------------------------ --min-rate, --progress

@test "--min-rate stops early and the header records the depth reached" {
  args="twin --n 1000 --k 1:1e5 --pmax 1e11"
  run --separate-stderr sieve $args --newpgen --min-rate 1e12 --rate-window 0.3
  assert_success
  [ -n "$output" ]
  [[ "$stderr" == *"--min-rate"* ]]
  echo "$output" > early.npg
  depth=$(head -1 early.npg | cut -d: -f1)
  [ "$depth" -gt 1048576 ]
  [ "$depth" -lt 100000000000 ]
  [[ "$stderr" == *"stopped at p = $depth"* ]]
  # The survivors are exactly those of a full run to that depth.
  sieve twin --n 1000 --k 1:1e5 --pmax "$depth" --newpgen > full.npg
  run cmp early.npg full.npg
  assert_success
  # ABC headers record it as well.
  run --separate-stderr sieve $args --abc --min-rate 1e12 --rate-window 0.3
  assert_success
  assert_line --index 0 --regexp '^ABC \$a\*2\^1000\+1 & \$a\*2\^1000-1 // Sieved to [0-9]+$'
  [[ "${lines[0]}" != *"Sieved to 100000000000" ]]
}

@test "--progress writes lines with 'left' on stderr and keeps stdout data only" {
  # Lines come every 2 s when stderr is not a terminal; --min-rate with a 2.5 s
  # window ends the run soon after, whatever the machine's speed.
  sieve twin --n 1000 --k 1:1e5 --pmax 1e11 --progress --min-rate 1e12 --rate-window 2.5 > out.jsonl 2> err.txt
  run cat err.txt
  assert_line --regexp '^sieve: p = [0-9]+, [0-9]+ left, '
  [ "$(wc -l < out.jsonl)" -gt 10 ]
  run grep -vc '^{"k":[0-9]*,"n":1000,"form":"twin"}$' out.jsonl
  assert_output "0"
}

# ------------------------------------------------------------ errors

# expect_error STATUS TEXT ARGS...: sieve ARGS exits with STATUS, the message
# names TEXT, and an exit-1 error is a single 'sieve: ' line.
expect_error() {
  local want=$1 text=$2
  shift 2
  run sieve "$@"
  if [ "$status" -ne "$want" ]; then
    echo "sieve $*: exit $status, expected $want; output: $output"
    return 1
  fi
  if [[ "$output" != *"$text"* ]]; then
    echo "sieve $*: output lacks '$text': $output"
    return 1
  fi
  if [ "$want" -eq 1 ] && { [ "${#lines[@]}" -ne 1 ] || [[ "${lines[0]}" != "sieve: "* ]]; }; then
    echo "sieve $*: not one 'sieve: ' line: $output"
    return 1
  fi
  if [ "$want" -eq 2 ] && [[ "$output" != *"Try 'sieve --help' for more information."* ]]; then
    echo "sieve $*: no pointer to --help: $output"
    return 1
  fi
}

@test "bad option values are usage errors (exit 2) naming the option; an unwritable file is exit 1" {
  expect_error 2 "empty" primes 10 5
  expect_error 2 "empty" twin --n 5 --k 10:1 --pmax 100
  expect_error 2 "empty" twin --n 5 --h0 15 --c 30 --x 10:1 --pmax 100
  expect_error 2 "exponent n" twin --n 0 --k 1:10 --pmax 100
  expect_error 2 "negative" twin --n -1 --k 1:10 --pmax 100
  expect_error 2 "negative" twin --n 5 --k -1:10 --pmax 100
  expect_error 2 "negative" twin --n 5 --h0 -15 --c 30 --x 1:10 --pmax 100
  expect_error 2 "negative" twin --n 5 --h0 15 --c -30 --x 1:10 --pmax 100
  expect_error 2 "negative" twin --n 5 --k 1:10 --pmax -7
  expect_error 2 "negative" primes -1 10
  expect_error 2 "c = 0" twin --n 5 --h0 15 --c 0 --x 1:10 --pmax 100
  expect_error 2 "chain length" cc1 --length 1 --n 5 --k 1:10 --pmax 100
  expect_error 2 "chain length" cc2 --length 65 --n 5 --k 1:10 --pmax 100
  expect_error 2 "at least 3" twin --n 5 --k 1:10 --pmax 2
  expect_error 2 "k must start at 1" twin --n 5 --k 0:10 --pmax 100
  expect_error 2 "18446744073709551616" twin --n 5 --k 1:18446744073709551616 --pmax 100
  expect_error 2 "18446744073709551616" twin --n 5 --k 1:10 --pmax 18446744073709551616
  expect_error 2 "64 bits" twin --n 1e20 --k 1:10 --pmax 100
  expect_error 2 "64 bits" twin --n 5 --h0 1 --c 2^40 --x 0:2^30 --pmax 100
  expect_error 2 "64 bits" primes 1 2^64
  expect_error 2 "2^32" twin --n 2^40 --k 1:10 --pmax 100
  expect_error 2 "2^36" twin --n 5 --k 1:2^37 --pmax 100
  expect_error 2 "not a non-negative integer" twin --n 5 --k 1:10 --pmax abc
  expect_error 2 "whole number" twin --n 5 --k 1:1.05e1 --pmax 100
  expect_error 2 "2^40+100" primes 1 2^40+100
  expect_error 2 "--k" twin --n 5 --k 1-10 --pmax 100
  expect_error 2 "--shard" twin --n 5 --k 1:10 --pmax 100 --shard 4/3
  expect_error 2 "--shard" twin --n 5 --k 1:10 --pmax 100 --shard 0/3
  expect_error 2 "--shard" twin --n 5 --k 1:10 --pmax 100 --shard three
  expect_error 2 "--pmax" twin --n 5 --k 1:10 --pmax abc
  expect_error 2 "--n" twin --n 0 --k 1:10 --pmax 100
  expect_error 2 "--checkpoint-every" twin --n 5 --k 1:10 --pmax 100 --checkpoint-every 0
  expect_error 2 "--min-rate" twin --n 5 --k 1:10 --pmax 100 --min-rate -1
  expect_error 2 "--rate-window" twin --n 5 --k 1:10 --pmax 100 --rate-window 0
  expect_error 2 "--rate-window" twin --n 5 --k 1:10 --pmax 100 --rate-window -5
  expect_error 2 "--rate-window" twin --n 5 --k 1:10 --pmax 100 --rate-window nan
  expect_error 2 "--rate-window" twin --n 5 --k 1:10 --pmax 100 --rate-window inf
  expect_error 1 "no-such-dir/f.txt" twin --n 5 --k 1:10 --pmax 100 --factors no-such-dir/f.txt
}

@test "a decimal number above 2^64-1 is said not to fit in 64 bits" {
  expect_error 2 "64 bits" twin --n 5 --k 1:18446744073709551616 --pmax 100
  expect_error 2 "64 bits" twin --n 5 --k 1:10 --pmax 18446744073709551616
  expect_error 2 "64 bits" primes 1 18446744073709551616
}

@test "the smallest edge values are accepted" {
  run sieve twin --n 1 --k 1:1 --pmax 3
  assert_success
  assert_output '{"k":1,"n":1,"form":"twin"}'
  run sieve cc2 --length 64 --n 1 --k 1:100 --pmax 3
  assert_success
  run sieve proth --n 5 --k 1e3:1.1e3 --pmax 2^10 --newpgen
  assert_success
  assert_line --index 0 "1024:P:1:2:1"
}

@test "usage errors exit 2 and point to --help" {
  expect_error 2 "--n" twin --k 1:10 --pmax 100
  expect_error 2 "--pmax" twin --n 5 --k 1:10
  expect_error 2 "--k" twin --n 5 --pmax 100
  expect_error 2 "--k" twin --n 5 --k 1:10 --h0 15 --c 30 --x 1:5 --pmax 100
  expect_error 2 "--h0" twin --n 5 --h0 15 --x 1:5 --pmax 100
  expect_error 2 "--abc" twin --n 5 --k 1:10 --pmax 100 --newpgen --abc
  expect_error 2 "--abcd" twin --n 5 --k 1:10 --pmax 100 --abc --abcd
  expect_error 2 "--csv" twin --n 5 --k 1:10 --pmax 100 --csv --newpgen
  expect_error 2 "--csv" --csv twin --n 5 --k 1:10 --pmax 100 --abcd
  expect_error 2 "--length" twin --n 5 --k 1:10 --pmax 100 --length 3
  expect_error 2 "threads" twin --n 5 --k 1:10 --pmax 100 -j 0
}

@test "a prime dividing c that divides every candidate is an error" {
  need_gp
  # k = 1 + 30x: every k*2^2-1 = 4k-1 is 0 mod 3 (4*1-1 = 3).
  expect_error 1 "divisible by 3" twin --n 2 --h0 1 --c 30 --x 0:100 --pmax 100
  # k = 1 + 7x: k*2^3-1 = 8k-1 is 0 mod 7.
  expect_error 1 "divisible by 7" riesel --n 3 --h0 1 --c 7 --x 1:100 --pmax 100
  # k = 2 + 5x: k*2^1+1 = 2k+1 is 0 mod 5, for proth but not for riesel.
  expect_error 1 "divisible by 5" proth --n 1 --h0 2 --c 5 --x 1:100 --pmax 100
  run sieve riesel --n 1 --h0 2 --c 5 --x 1:100 --pmax 100
  assert_success
  # A prime above 2^20: q = 1048583 divides c = 2q and h0*2^50-1 (h0 = 2^-50 mod q, made odd).
  read -r q h0 < <(gp_lines 'q = nextprime(2^20 + 1); h = lift(Mod(2, q)^-50); if(h % 2 == 0, h += q); print(q, " ", h)')
  expect_error 1 "divisible by $q" riesel --n 50 --h0 "$h0" --c $((2 * q)) --x 0:100 --pmax 2e6
  # ...but only when the sieve reaches it.
  run sieve riesel --n 50 --h0 "$h0" --c $((2 * q)) --x 0:100 --pmax 1e6
  assert_success
}

@test "--riesel-condition passes for h0 odd, 13 | c, k < 2^n and (13/N) = -1, and fails otherwise" {
  need_gp
  # The smallest odd h0 for which, with c = 30030 = 2*3*5*7*11*13, no prime
  # of c divides h0*2^20+-1 and h0*2^20-1 is a non-residue mod 13.
  h0=$(gp_lines 'forstep(h = 1, 999, 2, if(kronecker(h*2^20 - 1, 13) == -1 && gcd(h^2*2^40 - 1, 15015) == 1, print(h); break))')
  [ -n "$h0" ]
  # x <= 30 keeps k = h0 + 30030x below 2^20.
  [ $((h0 + 30030 * 30)) -lt 1048576 ]
  run sieve twin --n 20 --h0 "$h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  assert_success
  sieve twin --n 20 --h0 "$h0" --c 30030 --x 0:30 --pmax 1e5 > plain.txt
  [ "$output" = "$(cat plain.txt)" ]
  # For sg both k*2^20-1 and k*2^21-1 must be non-residues.
  sg_h0=$(gp_lines 'forstep(h = 1, 999, 2, if(kronecker(h*2^20 - 1, 13) == -1 && kronecker(h*2^21 - 1, 13) == -1 && gcd((h*2^20 - 1)*(h*2^21 - 1), 15015) == 1, print(h); break))')
  run sieve sg --n 20 --h0 "$sg_h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  assert_success
  # Proth and cc2 have no k*2^e-1 member for the condition to be about.
  expect_error 2 "has none" proth --n 20 --h0 "$h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  expect_error 2 "has none" cc2 --n 20 --h0 "$h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  # A residue: the smallest such h0 that is otherwise valid.
  bad_h0=$(gp_lines 'forstep(h = 1, 999, 2, if(kronecker(h*2^20 - 1, 13) == 1 && gcd(h^2*2^40 - 1, 15015) == 1, print(h); break))')
  expect_error 2 "13" twin --n 20 --h0 "$bad_h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  run sieve twin --n 20 --h0 "$bad_h0" --c 30030 --x 0:30 --pmax 1e5
  assert_success
  # k reaching 2^20.
  expect_error 2 "2^20" twin --n 20 --h0 "$h0" --c 30030 --x 0:40 --pmax 1e5 --riesel-condition
  # 13 does not divide c = 2310.
  expect_error 2 "13" twin --n 20 --h0 "$h0" --c 2310 --x 0:30 --pmax 1e5 --riesel-condition
  # Even k: proved as (k/2^t)*2^(20+t)-1, whose k is odd; N mod 13 is the
  # same for every x when 13 | c, whatever the parity of h0 and c.
  even_h0=$(gp_lines 'forstep(h = 0, 999, 2, if(kronecker(h*2^20 - 1, 13) == -1 && gcd(h^2*2^40 - 1, 15015) == 1, print(h); break))')
  run sieve twin --n 20 --h0 "$even_h0" --c 30030 --x 0:30 --pmax 1e5 --riesel-condition
  assert_success
  # A plain range of several k: (13/N) changes with k.
  expect_error 2 "13" twin --n 20 --k 1:31 --pmax 1e5 --riesel-condition
}

# ------------------------------------------------------------ mrtest pipeline

@test "NewPGen, ABC, ABCD and JSON Lines output piped into mrtest: every member prime when pmax^2 > largest member" {
  skip_volume_when_sanitized
  # n = 3, k <= 2000: members below 2000*2^5+1 = 64001 < 300^2.
  set -o pipefail
  for form in twin sg "cc1 --length 3" "cc2 --length 3" riesel proth; do
    survivors=$(sieve $form --n 3 --k 1:2000 --pmax 300 | wc -l)
    [ "$survivors" -gt 5 ]
    : > verdicts.jsonl
    for format in --newpgen --abc --abcd ""; do
      sieve $form --n 3 --k 1:2000 --pmax 300 $format | mrtest >> verdicts.jsonl
    done
    run bash -c "json-field verdict < verdicts.jsonl | sort | uniq -c"
    assert_success
    assert_output --regexp "^ *$((4 * survivors)) prime$"
  done
}

@test "a twin file piped into mrtest keeps k and n" {
  run bash -c "set -o pipefail; sieve twin --n 1 --k 1:20 --pmax 1000 --newpgen | mrtest | json-field k | tr '\n' ' '"
  assert_success
  assert_output "1 2 3 6 9 15 "
}

# ------------------------------------------------------------ primes

@test "sieve primes: plain lines, --count, --json and --csv shapes" {
  run --separate-stderr sieve primes 1 30
  assert_success
  assert_output "2
3
5
7
11
13
17
19
23
29"
  run sieve primes 1 30 --count
  assert_output "10"
  run sieve primes 1 30 --json
  assert_line --index 0 '{"number":2}'
  assert_line --index 9 '{"number":29}'
  [ "${#lines[@]}" -eq 10 ]
  run sieve primes 1 30 --count --json
  assert_output '{"from":1,"to":30,"count":10}'
  run sieve primes 1 30 --csv
  assert_line --index 0 'number'
  assert_line --index 1 '2'
  [ "${#lines[@]}" -eq 11 ]
  run sieve primes 1 30 --count --csv
  assert_output 'from,to,count
1,30,10'
  run sieve --csv primes 1 30 --count
  assert_output 'from,to,count
1,30,10'
}

@test "sieve primes: A and B as 1e9, 1.1e9 and 2^40; a one-number interval; primes above 2^53 as strings" {
  run sieve primes 1e9 1.1e9 --count
  assert_success
  [[ "$output" =~ ^[0-9]+$ ]]
  run sieve primes 1000000000 1100000000 --count
  expected=$output
  run sieve primes 1e9 1.1e9 --count
  assert_output "$expected"
  run sieve primes 2^40 1099511627791
  assert_success
  assert_output "1099511627791"  # 2^40+15, the first prime after 2^40
  run sieve primes 97 97
  assert_output "97"
  run sieve primes 98 100 --count
  assert_output "0"
  run --separate-stderr sieve primes 24 28
  assert_success
  assert_output ""
  # 2^53+5, the first prime above 2^53, does not fit a double: a string.
  run sieve primes 9007199254740992 9007199254741000 --json
  assert_output '{"number":"9007199254740997"}'
  run sieve primes 9007199254740881 9007199254740881 --json
  assert_output '{"number":9007199254740881}'
}

@test "sieve primes -j 2 writes the same list as -j 1" {
  sieve primes 1000000000 1020000000 -j 1 > one.txt
  sieve primes 1000000000 1020000000 -j 2 > two.txt
  run cmp one.txt two.txt
  assert_success
  [ "$(wc -l < one.txt)" -gt 900000 ]
}

@test "write errors on stdout are reported" {
  run bash -c "sieve twin --n 5 --k 1:100 --pmax 100 > /dev/full"
  assert_failure 1
  assert_output --partial "sieve: "
  run bash -c "sieve primes 1 1000 > /dev/full"
  assert_failure 1
  assert_output --partial "sieve: "
  run bash -c "sieve twin --n 5 --k 1:100 --pmax 100 --newpgen > /dev/full"
  assert_failure 1
  assert_output --partial "sieve: "
}
