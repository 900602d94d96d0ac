#!/usr/bin/env bats
# Command-line behaviour of subtune: the sub-tuning filter on small streams
# worked out by hand (the arithmetic is in the comments), the record formats,
# the errors and the usage errors of the filter, model, feed, correct and
# --simulate. The random streams, the t table, the ARLs and the model fit are
# checked against SciPy in subtune_oracle.bats.

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

# The four sizes of the hand-worked example.
four() { printf '%s\n' 10.000 10.002 10.001 10.003; }

@test "--help, --version and the subcommands' help" {
  run subtune --help
  assert_success
  for option in --alpha --alternative --statistic --min-parts --resolution --correct-to --field --lower --upper \
    --nominal --csv --simulate --policy --arl-runs --seed --shift --drift --ewma-lambda --cusum-k --cusum-h model feed correct; do
    assert_output --partial -- "$option"
  done
  run subtune --version
  assert_success
  assert_output --regexp '^subtune \(toolkit\) [0-9]+\.[0-9]+\.[0-9]+ \(revision [0-9A-Za-z._-]+\)$'
  run subtune model --help
  assert_success
  assert_output --partial "--residuals"
  run subtune feed --help
  assert_success
  for option in --model --coefficients --target --feed-min --feed-max; do assert_output --partial -- "$option"; done
  run subtune correct --help
  assert_success
  assert_output --partial "--feed"
}

@test "hand-worked, eq. (3)-(6) as printed (--statistic paper): 10.000 10.002 10.001 10.003 - a, b, S_N, t, t_crit at df 6, subtune, correction -N b" {
  # i = 1..4, mean i = 2.5, mean y = 10.0015, Sxx = 2.25 + 0.25 + 0.25 + 2.25 = 5,
  # Sxy = (-1.5)(-0.0015) + (-0.5)(0.0005) + (0.5)(-0.0005) + (1.5)(0.0015) = 0.004,
  # b = 0.004 / 5 = 0.0008, a = 10.0015 - 2.5 b = 9.9995;
  # fitted 10.0003 10.0011 10.0019 10.0027, residuals -0.0003 0.0009 -0.0009 0.0003,
  # SSE = 1.8e-6, S_N = sqrt(1.8e-6 / 3) = 7.745967e-4,
  # t = N |b| / S_N sqrt(N / 2) = 0.0032 / 7.745967e-4 * sqrt(2) = 5.842374 > 2.446912
  # (Student t, two-sided 5 %, df 2 (N - 1) = 6): subtune, correction a - A_T(4) = -4 b = -0.0032.
  # Before: N = 2: b = 0.002, a = 9.998; N = 3: b = 0.0005, a = 10.0 (Sxy = 0.001, Sxx = 2).
  four > four.txt
  subtune --statistic paper four.txt > out.jsonl
  run check '
assert len(rows) == 4
keys = ["size", "run", "n", "a", "b", "s", "t", "t_crit", "df", "decision", "correction", "offset"]
assert all(list(r) == keys for r in rows), list(rows[0])
for k, r in enumerate(rows[:3]):
    assert r["run"] == 1 and r["n"] == k + 1 and r["decision"] == "insufficient", r
    assert r["s"] is None and r["t"] is None and r["t_crit"] is None and r["df"] is None, r
    assert r["correction"] == 0 and r["offset"] == 0, r
assert rows[0]["a"] is None and rows[0]["b"] is None
assert near(rows[1]["b"], 0.002, 1e-12) and near(rows[1]["a"], 9.998, 1e-12), rows[1]
assert near(rows[2]["b"], 0.0005, 1e-12) and near(rows[2]["a"], 10.0, 1e-12), rows[2]
r = rows[3]
assert near(r["a"], 9.9995, 1e-12) and near(r["b"], 0.0008, 1e-12), r
assert near(r["s"], 7.745967e-4, 1e-9), r
assert near(r["t"], 5.842374, 1e-5), r
assert near(r["t_crit"], 2.446912, 1e-6) and r["df"] == 6, r
assert r["decision"] == "subtune" and r["n"] == 4, r
assert near(r["correction"], -0.0032, 1e-12) and near(r["offset"], -0.0032, 1e-12), r
' < out.jsonl
  assert_output "ok"
}

@test "after a subtune the next part opens a new run; the offset adds up the corrections" {
  # Run 2 repeats run 1's shape 3 um higher: again b = 0.0008, correction -0.0032;
  # the offset reaches -0.0064. Part 9 opens run 3.
  { four; printf '%s\n' 10.003 10.005 10.004 10.006 10.1; } > eight.txt
  subtune --statistic paper eight.txt > out.jsonl
  run check '
assert [r["run"] for r in rows] == [1, 1, 1, 1, 2, 2, 2, 2, 3]
assert [r["n"] for r in rows] == [1, 2, 3, 4, 1, 2, 3, 4, 1]
assert [r["decision"] for r in rows] == ["insufficient"] * 3 + ["subtune"] + ["insufficient"] * 3 + ["subtune", "insufficient"]
assert rows[4]["a"] is None and near(rows[4]["offset"], -0.0032, 1e-12), rows[4]
assert near(rows[7]["a"], 10.0025, 1e-9) and near(rows[7]["b"], 0.0008, 1e-9), rows[7]
assert near(rows[7]["correction"], -0.0032, 1e-9) and near(rows[7]["offset"], -0.0064, 1e-9), rows[7]
assert near(rows[8]["offset"], -0.0064, 1e-9) and rows[8]["correction"] == 0, rows[8]
' < out.jsonl
  assert_output "ok"
}

@test "--min-parts: no decision before N parts; --min-parts 3 tests the third part" {
  # N = 3 with 10.000 10.002 10.001: b = 0.0005, a = 10.0, fitted 10.0005 10.001 10.0015,
  # residuals -0.0005 0.001 -0.0005, SSE = 1.5e-6, S = sqrt(1.5e-6 / 2) = 8.660254e-4,
  # t = 3 * 0.0005 / S * sqrt(1.5) = 2.121320 < t(0.975, 4) = 2.776445: none.
  four | subtune --statistic paper --min-parts 3 > out.jsonl
  run check '
assert [r["decision"] for r in rows][:3] == ["insufficient", "insufficient", "none"], rows
r = rows[2]
assert near(r["s"], 8.660254e-4, 1e-9) and near(r["t"], 2.121320, 1e-5) and r["df"] == 4, r
assert near(r["t_crit"], 2.776445, 1e-6), r
' < out.jsonl
  assert_output "ok"
  four | subtune --statistic paper --min-parts 5 > out.jsonl
  run check 'assert all(r["decision"] == "insufficient" and r["t"] is None for r in rows), rows' < out.jsonl
  assert_output "ok"
}

@test "identical sizes: S_N = 0, b = 0, t = 0, decision none for every N" {
  printf '25.4\n%.0s' $(seq 8) | subtune --statistic paper > out.jsonl
  run check '
assert [r["decision"] for r in rows] == ["insufficient"] * 3 + ["none"] * 5, rows
for r in rows[3:]:
    assert r["b"] == 0 and r["s"] == 0 and r["t"] == 0 and r["a"] == 25.4 and r["offset"] == 0, r
    assert r["df"] == 2 * (r["n"] - 1)
' < out.jsonl
  assert_output "ok"
}

@test "perfectly linear sizes: t infinite (null), subtune; --resolution r puts S_N at r/sqrt(12)" {
  printf '%s\n' 0.1 0.2 0.3 0.4 | subtune --statistic paper > out.jsonl
  run check '
r = rows[3]
assert r["decision"] == "subtune" and (r["t"] is None or r["t"] > 1e6), r
assert near(r["b"], 0.1, 1e-12) and near(r["correction"], -0.4, 1e-12), r' < out.jsonl
  assert_output "ok"
  # r = 0.01: S = 0.01 / sqrt(12) = 2.886751e-3, t = 4 * 0.1 / S * sqrt(2) = 195.9592
  printf '%s\n' 0.1 0.2 0.3 0.4 | subtune --statistic paper --resolution 0.01 > out.jsonl
  run check '
r = rows[3]
assert near(r["s"], 2.886751e-3, 1e-9) and near(r["t"], 195.9592, 1e-3) and r["decision"] == "subtune", r' < out.jsonl
  assert_output "ok"
  # The gauge floor also keeps the hand-worked stream below significance:
  # r = 0.005: S = 1.443376e-3 > 7.75e-4, t = 0.0032 / S * sqrt(2) = 3.135347 > 2.446912 still;
  # r = 0.01: S = 2.886751e-3, t = 1.567673 < 2.446912: none.
  four | subtune --statistic paper --resolution 0.005 > out.jsonl
  run check 'assert near(rows[3]["t"], 3.135347, 1e-5) and rows[3]["decision"] == "subtune", rows[3]' < out.jsonl
  assert_output "ok"
  four | subtune --statistic paper --resolution 0.01 > out.jsonl
  run check 'assert near(rows[3]["t"], 1.567673, 1e-5) and rows[3]["decision"] == "none" and rows[3]["correction"] == 0, rows[3]' < out.jsonl
  assert_output "ok"
}

@test "the default, --statistic slope: s^2 = SSE/(N-2), t = |b| sqrt(Sxx)/s at N-2 df" {
  # s = sqrt(1.8e-6 / 2) = 9.486833e-4, t = 0.0008 sqrt(5) / s = 1.885618 < t(0.975, 2) = 4.302653.
  for statistic in "" "--statistic slope"; do
    # shellcheck disable=SC2086
    four | subtune $statistic > out.jsonl
    run check '
r = rows[3]
assert near(r["s"], 9.486833e-4, 1e-9) and near(r["t"], 1.885618, 1e-5), r
assert r["df"] == 2 and near(r["t_crit"], 4.302653, 1e-6) and r["decision"] == "none", r' < out.jsonl
    assert_output "ok"
  done
}

@test "--alternative greater/less: one-sided t_crit (1.943180 at df 6); only the matching direction sub-tunes" {
  four | subtune --statistic paper --alternative greater > out.jsonl
  run check 'r = rows[3]; assert near(r["t_crit"], 1.943180, 1e-6) and r["decision"] == "subtune", r' < out.jsonl
  assert_output "ok"
  four | subtune --statistic paper --alternative less > out.jsonl
  run check 'r = rows[3]; assert near(r["t_crit"], 1.943180, 1e-6) and r["decision"] == "none" and r["correction"] == 0, r' < out.jsonl
  assert_output "ok"
  # the mirror image (shrinking sizes) sub-tunes with less: correction +0.0032
  printf '%s\n' 10.003 10.001 10.002 10.000 | subtune --statistic paper --alternative less > out.jsonl
  run check 'r = rows[3]; assert r["decision"] == "subtune" and near(r["correction"], 0.0032, 1e-12), r' < out.jsonl
  assert_output "ok"
}

@test "--correct-to nominal --nominal X: correction X - A_T(N); without --nominal a usage error" {
  # A_T(4) = 9.9995 + 4 * 0.0008 = 10.0027; to 10: -0.0027; to 10.01: +0.0073.
  four | subtune --statistic paper --correct-to nominal --nominal 10 > out.jsonl
  run check 'assert near(rows[3]["correction"], -0.0027, 1e-12) and near(rows[3]["offset"], -0.0027, 1e-12), rows[3]' < out.jsonl
  assert_output "ok"
  four | subtune --statistic paper --correct-to nominal --nominal 10.01 > out.jsonl
  run check 'assert near(rows[3]["correction"], 0.0073, 1e-12), rows[3]' < out.jsonl
  assert_output "ok"
  run subtune --correct-to nominal < /dev/null
  [ "$status" -eq 2 ]
}

@test "input formats: CSV with header (ids pass through, CRLF too), a bare column, JSON Lines, --field, several files" {
  printf 'id,size\nP1,10.000\nP2,10.002\nP3,10.001\nP4,10.003\n' > parts.csv
  subtune --statistic paper parts.csv > csv.jsonl
  run check '
assert [r["id"] for r in rows] == ["P1", "P2", "P3", "P4"]
assert list(rows[0])[:2] == ["id", "size"] and float(rows[0]["size"]) == 10.0
assert rows[3]["decision"] == "subtune" and near(rows[3]["t"], 5.842374, 1e-5), rows[3]' < csv.jsonl
  assert_output "ok"
  printf 'id,size\r\nP1,10.000\r\nP2,10.002\r\nP3,10.001\r\nP4,10.003\r\n' | subtune --statistic paper > crlf.jsonl
  run check 'assert [r["id"] for r in rows] == ["P1", "P2", "P3", "P4"] and near(rows[3]["t"], 5.842374, 1e-5)' < crlf.jsonl
  assert_output "ok"
  four | subtune --statistic paper - > bare.jsonl
  run check 'assert [r["size"] for r in rows] == [10.0, 10.002, 10.001, 10.003] and rows[3]["decision"] == "subtune"' < bare.jsonl
  assert_output "ok"
  printf '{"part":"A","d":10.000}\n{"part":"B","d":10.002}\n{"part":"C","d":10.001}\n{"part":"D","d":10.003}\n' > parts.jsonl
  subtune --statistic paper --field d parts.jsonl > json.jsonl
  run check 'assert [r["part"] for r in rows] == list("ABCD") and near(rows[3]["t"], 5.842374, 1e-5)' < json.jsonl
  assert_output "ok"
  # two files are one stream
  printf '10.000\n10.002\n' > first.txt
  printf '10.001\n10.003\n' > second.txt
  subtune --statistic paper first.txt second.txt > two.jsonl
  run check 'assert [r["n"] for r in rows] == [1, 2, 3, 4] and rows[3]["decision"] == "subtune"' < two.jsonl
  assert_output "ok"
}

@test "--csv: the header row, the same figures as JSON Lines, empty cells for nulls" {
  four > four.txt
  subtune four.txt > out.jsonl
  subtune --csv four.txt > out.csv
  run head -1 out.csv
  # in_tolerance is always a CSV column (any record may bring limits), empty without limits
  assert_output "size,run,n,a,b,s,t,t_crit,df,decision,correction,offset,in_tolerance"
  [ "$(wc -l < out.csv)" -eq 5 ]
  run py '
import csv, json
rows = [json.loads(l) for l in open("out.jsonl")]
cells = list(csv.DictReader(open("out.csv")))
for r, c in zip(rows, cells):
    for k, v in r.items():
        if v is None:
            assert c[k] == "", (k, c[k])
        elif isinstance(v, str):
            assert c[k] == v, (k, c[k])
        else:
            assert float(c[k]) == v, (k, c[k], v)
print("ok")'
  assert_output "ok"
}

@test "--csv from CSV: the input columns pass through in their order, then the tool's" {
  printf 'id,size,note\nP1,10.000,x\nP2,10.002,y\n' > parts.csv
  run subtune --csv parts.csv
  assert_success
  assert_line --index 0 "id,size,note,run,n,a,b,s,t,t_crit,df,decision,correction,offset,in_tolerance"
  assert_line --index 1 --partial "P1,10.000,x,1,1,"
  run subtune parts.csv
  assert_line --index 0 --regexp '^\{"id":"P1","size":"?10.000"?,"note":"x","run":1,'
}

@test "in_tolerance: --lower/--upper, a record's own limits override them, absent without limits" {
  printf '{"size":10.00}\n{"size":10.06}\n{"size":9.94,"lower":9.9}\n{"size":10.02,"upper":10.01}\n{"size":10.05}\n' > tol.jsonl
  subtune --lower 9.95 --upper 10.05 tol.jsonl > out.jsonl
  run check 'assert [r["in_tolerance"] for r in rows] == [True, False, True, False, True], rows' < out.jsonl
  assert_output "ok"
  subtune --upper 10.03 tol.jsonl > out.jsonl
  run check 'assert [r["in_tolerance"] for r in rows] == [True, False, True, False, False], rows' < out.jsonl
  assert_output "ok"
  printf '10\n10.1\n' | subtune > out.jsonl
  run check 'assert all("in_tolerance" not in r for r in rows)' < out.jsonl
  assert_output "ok"
  printf '10\n10.1\n' | subtune --csv --lower 9.95 --upper 10.05 > out.csv
  run head -1 out.csv
  assert_output "size,run,n,a,b,s,t,t_crit,df,decision,correction,offset,in_tolerance"
}

@test "--csv with limits on only some CSV rows: an in_tolerance column, empty where a row has no limits" {
  printf 'id,size,lower,upper\nA,10.00,,\nB,10.02,9.99,10.01\nC,10.00,9.99,10.01\n' > some.csv
  run --separate-stderr subtune --csv some.csv
  echo "$stderr"
  assert_success
  assert_line --index 0 "id,size,lower,upper,run,n,a,b,s,t,t_crit,df,decision,correction,offset,in_tolerance"
  [ "${#lines[@]}" -eq 4 ]
}

@test "empty input: no records and exit 0 (stdin, an empty file, blank lines, a header-only CSV; with --csv no header)" {
  run --separate-stderr subtune < /dev/null
  assert_success
  [ -z "$output" ] && [ -z "$stderr" ]
  : > empty.txt
  run --separate-stderr subtune --csv empty.txt
  assert_success
  [ -z "$output" ]
  run --separate-stderr subtune <<< $'\n\n'
  assert_success
  [ -z "$output" ]
  run --separate-stderr subtune <<< 'size'
  assert_success
  [ -z "$output" ]
}

# bad_line FILE LINE: exit 1, one stderr line "subtune: FILE:LINE: ...", the
# records before the bad line on stdout.
bad_line() {
  run --separate-stderr subtune "$1"
  echo "stderr: $stderr"
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == "subtune: $1:$2: "* ]]
  [ "${#lines[@]}" -eq $(($2 - 1 - ${3:-0})) ]
}

@test "bad sizes: abc, nan, inf, -inf, 1e999 exit 1 with file:line on one stderr line; earlier records stay written" {
  for bad in abc nan NaN inf -inf 1e999 '10.0.1' ''; do
    printf '10.000\n10.002\n%s\n10.001\n' "$bad" > bad.txt
    [ -n "$bad" ] || printf '10.000\n10.002\nx y\n' > bad.txt
    bad_line bad.txt 3
  done
  printf '{"size":10}\n{"size":10.1}\n{"size":"nan"}\n' > bad.jsonl
  bad_line bad.jsonl 3
  printf '{"size":10}\n{"size":10.1}\n{"size":1e999}\n' > bad.jsonl
  bad_line bad.jsonl 3
  printf '{"size":10}\n{"size":10.1}\n{"size":NaN}\n' > bad.jsonl
  bad_line bad.jsonl 3
  printf '{"size":10}\n{"size":10.1}\n{"size":null}\n' > bad.jsonl
  bad_line bad.jsonl 3
  printf 'size\n10\n10.1\nabc\n' > bad.csv
  bad_line bad.csv 4 1
  printf 'size\n10\n10.1\ninf\n' > bad.csv
  bad_line bad.csv 4 1
}

@test "a missing size field, a short CSV row, binary garbage: exit 1, one stderr line, no crash" {
  printf '{"size":10}\n{"size":10.1}\n{"diameter":10}\n' > missing.jsonl
  bad_line missing.jsonl 3
  assert_equal "$(grep -c size <<< "$stderr")" 1
  printf 'id,size\nA,10\nB\n' > short.csv
  bad_line short.csv 3 1
  printf 'id,diameter\nA,10\n' > nosize.csv
  run --separate-stderr subtune nosize.csv
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == "subtune: nosize.csv:"* ]]
  printf '\x00\x01\xfe\xff\x7fELF\x02\x01\n\x80\x81\x82\n' > garbage.bin
  run --separate-stderr subtune garbage.bin
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == "subtune: garbage.bin:"* ]]
  py 'import random, sys
random.seed(1)
sys.stdout.buffer.write(bytes(random.randrange(256) for _ in range(4096)))' > random.bin
  run --separate-stderr subtune random.bin
  [ "$status" -eq 1 ]  # never a signal (>= 128)
  run --separate-stderr subtune no-such-file.txt
  [ "$status" -eq 1 ]
  [[ "$stderr" == "subtune: "*"no-such-file.txt"* ]]
}

@test "sizes beyond +-1e6 mm or nonzero below 1e-100 mm are bad data (exit 1, file:line); 1e6 and 1e-100 run" {
  for x in 1e300 -1e300 1e160 1.000001e6 1e7; do
    printf '10\n10.1\n%s\n10\n' $x > huge.txt
    bad_line huge.txt 3
  done
  printf '{"size":10}\n{"size":1e300}\n' > huge.jsonl
  bad_line huge.jsonl 2
  printf 'size\n10\n-2e6\n' > huge.csv
  bad_line huge.csv 3 1
  for x in 1e-170 1e-300 -1e-101; do
    printf '10\n10.1\n%s\n10\n' $x > tiny.txt
    bad_line tiny.txt 3
  done
  for x in 1e6 1e-100; do
    printf '%s\n-%s\n%s\n-%s\n%s\n' $x $x $x $x $x > alt.txt
    run --separate-stderr subtune alt.txt
    assert_success
    echo "$output" > out.jsonl
    run check 'assert len(rows) == 5 and all(math.isfinite(r["a"]) and math.isfinite(r["b"]) and math.isfinite(r["offset"]) for r in rows[1:4]), rows' < out.jsonl
    assert_output "ok"
  done
  # the allowance and the calibration values have the same bound
  printf '{"a":1}\n{"a":2e6}\n' > a.jsonl
  run --separate-stderr subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed 0.2 a.jsonl
  [ "$status" -eq 1 ]
  [[ "$stderr" == "subtune: a.jsonl:2: "* ]]
  [ "${#lines[@]}" -eq 1 ]
}

@test "the statistic does not depend on the unit: +-x alternating gives t = 2.190890 for x = 1, 1e6, 1e-6, 1e-100" {
  # +-x alternating, x = 1: b = -0.4, a = 1, residuals 0.4 -1.2 1.2 -0.4, SSE = 3.2,
  # S = sqrt(3.2 / 3) = 1.032796, t = 4 * 0.4 / S * sqrt(2) = 2.190890 < 2.446912: none.
  # Scaling every size by x scales a, b, S by x and leaves t and the decision alone.
  local x failed=0
  for x in 1 1e6 1e-6 1e-100; do
    printf '%s\n-%s\n%s\n-%s\n' $x $x $x $x > alt.txt
    subtune --statistic paper alt.txt > out.jsonl
    run check '
r = rows[3]
x = float("'$x'")
assert near(r["b"], -0.4 * x, 1e-9 * x) and near(r["s"], 1.032796 * x, 1e-6 * x), r
assert near(r["t"], 2.190890, 1e-5) and r["decision"] == "none", r' < out.jsonl
    echo "x = $x: ${output##*AssertionError: }"
    [ "$output" = ok ] || failed=1
  done
  [ "$failed" -eq 0 ]
}

@test "bad option values are usage errors (exit 2, 'Try' line)" {
  printf '10\n' > one.txt
  for args in "--alpha 0" "--alpha 1" "--alpha 2" "--alpha abc" "--alternative greater --alpha 0.5" "--alternative less --alpha 0.7" \
    "--min-parts 2" "--min-parts 0" "--resolution -1" "--lower 10 --upper 9" \
    "--statistic foo" "--alternative up" "--correct-to end" "--bogus" "--simulate one.txt" "--simulate --svg plot.svg" \
    "--simulate --parts 0" "--simulate --policy bogus" "--simulate --arl-runs 0" "--simulate --ewma-lambda 0" "--simulate --ewma-lambda 1.5"; do
    # shellcheck disable=SC2086
    run --separate-stderr subtune $args < /dev/null
    echo "$args -> $status: $stderr"
    [ "$status" -eq 2 ]
    [[ "$stderr" == *"Try 'subtune --help' for more information."* ]]
    [ -z "$output" ]
  done
}

@test "simulation options without --simulate are usage errors" {
  for args in "--parts 10" "--policy ewma" "--seed 3" "--arl-runs 100" "--shift 2" "--drift 0.2" "--wear 0.001" \
    "--process-sd 0.001" "--trace t.jsonl" "--ewma-lambda 0.3" "--cusum-h 4" "--sigma 0.002"; do
    # shellcheck disable=SC2086
    run --separate-stderr subtune $args < /dev/null
    echo "$args -> $status: $stderr"
    [ "$status" -eq 2 ]
    [ -z "$output" ]
  done
}

@test "--simulate: one summary per policy with the documented fields; --policy picks one" {
  run --separate-stderr subtune --simulate --parts 200 --arl-runs 50
  assert_success
  [ "${#lines[@]}" -eq 5 ]
  echo "$output" | check '
keys = ["policy", "parts", "in_tolerance_share", "mean_abs_deviation_mm", "rms_deviation_mm", "max_abs_deviation_mm",
        "corrections", "false_alarms", "arl0", "arl0_se", "arl_shift", "arl_shift_se", "arl_drift", "arl_drift_se", "sigma_mm"]
assert [r["policy"] for r in rows] == ["none", "subtune", "shewhart", "ewma", "cusum"], rows
for r in rows:
    assert list(r) == keys, list(r)
    assert r["parts"] == 200 and 0 <= r["in_tolerance_share"] <= 1
    assert 0 <= r["mean_abs_deviation_mm"] <= r["rms_deviation_mm"] <= r["max_abs_deviation_mm"], r
assert rows[0]["corrections"] == 0 and rows[0]["arl0"] is None
# sigma of the stable process: sqrt(process 0.002^2 + gauge 0.001^2 + (0.01 * allowance sd 0.2)^2) = 0.003
assert all(near(r["sigma_mm"], 0.003, 1e-12) for r in rows), rows
'
  run subtune --simulate --policy cusum --parts 50 --arl-runs 20
  assert_success
  [ "${#lines[@]}" -eq 1 ]
  assert_output --partial '"policy":"cusum"'
}

@test "model errors: 5 points, 2 feeds, collinear a and f exit 1 with one line" {
  printf '{"a":%s,"f":%s,"y":%s}\n' 0.5 0.1 0.01 1 0.2 0.02 1.5 0.3 0.03 2 0.1 0.02 0.5 0.3 0.02 > five.jsonl
  run --separate-stderr subtune model five.jsonl
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == *"6 points"* ]]
  [ -z "$output" ]
  printf '{"a":%s,"f":%s,"y":%s}\n' 0.5 0.1 0.01 1 0.1 0.02 1.5 0.1 0.03 0.5 0.2 0.02 1 0.2 0.03 1.5 0.2 0.04 2 0.2 0.05 > twofeeds.jsonl
  run --separate-stderr subtune model twofeeds.jsonl
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  [[ "$stderr" == *"feeds"* ]]
  printf '{"a":%s,"f":%s,"y":0.01}\n' 0.5 0.05 1 0.1 1.5 0.15 2 0.2 2.5 0.25 3 0.3 > line.jsonl
  run --separate-stderr subtune model line.jsonl
  [ "$status" -eq 1 ]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  run --separate-stderr subtune model < /dev/null
  [ "$status" -eq 1 ]
}

@test "model on an exact quadratic: the six coefficients back, r2 = 1" {
  # y = 0.002 + 0.008 a + 0.03 f + 0.01 a f + 0.001 a^2 + 0.05 f^2 on a 3 x 3 grid, no noise
  for a in 0.5 1 2; do for f in 0.1 0.2 0.4; do
    py "a, f = $a, $f; print('{\"a\": %r, \"f\": %r, \"y\": %r}' % (a, f, 0.002 + 0.008*a + 0.03*f + 0.01*a*f + 0.001*a*a + 0.05*f*f))"
  done; done > exact.jsonl
  subtune model exact.jsonl > model.json
  run check '
m = rows[0]
want = dict(b0=0.002, b1=0.008, b2=0.03, b12=0.01, b11=0.001, b22=0.05)
assert all(near(m[k], v, 1e-12) for k, v in want.items()), m
assert m["points"] == 9 and near(m["r2"], 1, 1e-12) and m["residual_sd"] < 1e-12, m' < model.json
  assert_output "ok"
}

@test "feed and correct: the model is required, once; --feed-min above --feed-max; bad coefficients" {
  printf '{"a":1}\n' > a.jsonl
  for cmd in "feed --target 0.02" "correct --feed 0.2"; do
    # shellcheck disable=SC2086
    run --separate-stderr subtune $cmd a.jsonl
    [ "$status" -eq 2 ]
    # shellcheck disable=SC2086
    run --separate-stderr subtune $cmd --coefficients 0,0,0,0,0,0.1 --model a.jsonl a.jsonl
    [ "$status" -eq 2 ]
  done
  run --separate-stderr subtune feed --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed-min 0.4 --feed-max 0.1 a.jsonl
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--feed-min"* ]]
  [ -z "$output" ]
  run --separate-stderr subtune feed --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed-min 0 a.jsonl
  [ "$status" -eq 2 ]
  run --separate-stderr subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed -1 a.jsonl
  [ "$status" -eq 2 ]
}

@test "feed and correct: a malformed --coefficients is a usage error (exit 2), as other bad option values" {
  printf '{"a":1}\n' > a.jsonl
  for c in 1,2,3 1,2,3,4,5,x 1,2,3,4,5,nan; do
    for cmd in "feed" "correct --feed 0.2"; do
      # shellcheck disable=SC2086
      run --separate-stderr subtune $cmd --coefficients "$c" a.jsonl
      echo "$cmd --coefficients $c -> $status: $stderr"
      [ "$status" -eq 2 ]
      [ -z "$output" ]
    done
  done
}

@test "feed and correct: bad records exit 1 with file:line; correct by hand" {
  printf '{"a":1}\n{"a":-1}\n' > neg.jsonl
  run --separate-stderr subtune feed --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 neg.jsonl
  [ "$status" -eq 1 ]
  [[ "$stderr" == "subtune: neg.jsonl:2: "* ]]
  [ "${#lines[@]}" -eq 1 ]
  printf '{"a":1}\n{"b":1}\n' > noa.jsonl
  run --separate-stderr subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed 0.2 noa.jsonl
  [ "$status" -eq 1 ]
  [[ "$stderr" == "subtune: noa.jsonl:2: "* ]]
  # no --feed and no f in the record
  run --separate-stderr subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 noa.jsonl
  [ "$status" -eq 1 ]
  [[ "$stderr" == "subtune: noa.jsonl:1: "*"--feed"* ]]
  # y(1, 0.2) = 0.002 + 0.008 + 0.006 + 0.002 + 0.001 + 0.002 = 0.021; y(2, 0.1) = 0.002 + 0.016
  # + 0.003 + 0.002 + 0.004 + 0.0005 = 0.0275 (the record's f wins over --feed)
  printf '{"a":1}\n{"a":2,"f":0.1}\n' | subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed 0.2 > out.jsonl
  run check '
assert near(rows[0]["predicted_error"], 0.021, 1e-15) and near(rows[0]["correction"], -0.021, 1e-15), rows[0]
assert near(rows[1]["predicted_error"], 0.0275, 1e-15) and near(rows[1]["correction"], -0.0275, 1e-15), rows[1]' < out.jsonl
  assert_output "ok"
}

@test "the filter under a chart: each part's statistic, limit, decision and offset as the chart's definition gives them" {
  # An independent recursion in Python over the wear fixture (0.4 µm/part drift):
  # Shewhart x − μ0 against 3σ; EWMA z = λ(x − μ0) + (1 − λ)z against
  # 3σ√(λ/(2 − λ)); tabular CUSUM C± with k = 0.5σ, h = 5σ; each restarts after
  # an alarm and corrects by −(x − μ0), −z, or −(±(K + C/N)) (Montgomery).
  local policy
  for policy in shewhart ewma cusum; do
    subtune --policy $policy --nominal 40 --sigma 0.003 "$FIXTURES/subtune/wear.txt" > $policy.jsonl
    run py '
import json, math, sys
policy = sys.argv[1]
rows = [json.loads(l) for l in open(policy + ".jsonl")]
mu, sigma, lam = 40.0, 0.003, 0.2
z = cp = cm = 0.0
np_ = nm = n = 0
offset = 0.0
alarms = 0
for r in rows:
    x = r["size"] - mu
    n += 1
    if policy == "shewhart":
        stat, limit = x, 3 * sigma
        level = r["size"]
        alarm = abs(x) > limit
        corr = -x if alarm else 0.0
    elif policy == "ewma":
        z = lam * x + (1 - lam) * z
        stat, limit = z, 3 * sigma * math.sqrt(lam / (2 - lam))
        level = mu + z
        alarm = abs(z) > limit
        corr = -z if alarm else 0.0
        if alarm: z = 0.0
    else:
        K, H = 0.5 * sigma, 5 * sigma
        cp, cm = max(0.0, cp + x - K), max(0.0, cm - x - K)
        np_ = np_ + 1 if cp > 0 else 0
        nm = nm + 1 if cm > 0 else 0
        stat, limit = (cp if cp >= cm else -cm), H
        # Montgomery: the mean estimated as mu +- (K + C/N) while a sum is above 0
        level = mu + ((K + cp / np_ if cp > 0 else 0.0) if cp >= cm else -(K + cm / nm))
        alarm = max(cp, cm) > H
        corr = (-(K + cp / np_) if cp >= cm else K + cm / nm) if alarm else 0.0
        if alarm: cp = cm = 0.0; np_ = nm = 0
    offset += corr
    assert abs(r["statistic"] - stat) < 1e-12 and abs(r["limit"] - limit) < 1e-15, (r, stat, limit)
    assert r["decision"] == ("adjust" if alarm else "none") and abs(r["correction"] - corr) < 1e-12, (r, corr)
    assert abs(r["offset"] - offset) < 1e-9 and r["n"] == n, (r, offset, n)
    assert abs(r["level"] - level) < 1e-12, (r, level)
    if alarm: n = 0; alarms += 1
assert len(rows) == 300 and alarms > 0, alarms
print("ok", alarms)' $policy
    echo "$policy: $output"
    assert_output --regexp '^ok [0-9]+$'
  done
}

@test "the filter under a chart needs --nominal and --sigma; chart options need a chart" {
  printf '40\n' > one.txt
  for args in "--policy ewma" "--policy cusum --nominal 40" "--policy shewhart --sigma 0.003" "--policy all" "--policy none" "--sigma 0.003" "--cusum-h 4"; do
    # shellcheck disable=SC2086
    run --separate-stderr subtune $args one.txt
    echo "$args -> $status: $stderr"
    [ "$status" -eq 2 ]
  done
}

@test "records that change shape mid-stream: bare sizes after full records and the reverse" {
  printf '{"id":1,"size":40}\n{"size":40.1}\n{"size":40.2,"id":3}\n' > mixed.jsonl
  run --separate-stderr subtune mixed.jsonl
  assert_success
  [ "${#lines[@]}" -eq 3 ]
  run check 'assert [r["n"] for r in rows] == [1, 2, 3] and rows[1]["size"] == 40.1 and rows[2]["id"] == 3' <<< "$output"
  assert_output "ok"
  printf '{"size":40}\n{"id":2,"size":40.1}\n' > mixed2.jsonl
  run --separate-stderr subtune mixed2.jsonl
  assert_success
  [ "${#lines[@]}" -eq 2 ]
}

@test "--svg: tick labels are plain numbers (1000, not 1e+03) on a 1-2-5 step" {
  subtune --simulate --parts 5000 --arl-runs 20 --policy ewma --svg plot.svg > /dev/null
  run py '
import math, re, xml.etree.ElementTree as E
N = "{http://www.w3.org/2000/svg}"
texts = [t for t in E.parse("plot.svg").getroot().iter(N + "text")]
# Every label that reads as a number is one: no exponent, plain digits.
numeric = []
for t in texts:
    text = (t.text or "").strip()
    try:
        float(text)
    except ValueError:
        continue
    assert not re.search(r"e[+-]", text, re.I), text
    assert re.fullmatch(r"-?[0-9]+(\.[0-9]+)?", text), text
    numeric.append(t)
# Axes: the labels of one row (time) or one column run (a panel), rising by a step of 1, 2 or 5 times a power of ten.
axes, last = [], None
for t in numeric:
    key = ("x", t.get("y")) if t.get("text-anchor") == "middle" else ("y", t.get("x"))
    value = float(t.text)
    if not axes or axes[-1][0] != key or value <= axes[-1][1][-1]:
        axes.append((key, []))
    axes[-1][1].append(value)
assert len(axes) == 3, axes  # two panels and the part-number axis
for key, values in axes:
    steps = {round(b - a, 9) for a, b in zip(values, values[1:])}
    assert len(steps) == 1 and len(values) >= 4, (key, values)
    step = steps.pop()
    mantissa = step / 10 ** math.floor(math.log10(step) + 1e-9)
    assert round(mantissa, 6) in (1, 2, 5), (key, step)
print(max(axes[-1][1]))'
  assert_output "5000.0"
}

@test "--simulate: --trace has a record per part and policy, --svg draws one policy, --compensate and --sim-model set sigma as the formula does" {
  subtune --simulate --parts 50 --arl-runs 20 --policy all --trace trace.jsonl > sum.jsonl
  [ "$(wc -l < trace.jsonl)" -eq 250 ]
  [ "$(wc -l < sum.jsonl)" -eq 5 ]
  run check 'assert set(r["policy"] for r in rows) == {"none", "subtune", "shewhart", "ewma", "cusum"} and all(0.1 < r["allowance"] for r in rows)' < trace.jsonl
  assert_output "ok"
  subtune --simulate --parts 50 --arl-runs 20 --policy ewma --svg plot.svg > /dev/null
  grep -q '<svg' plot.svg
  grep -q 'EWMA level' plot.svg
  # σ² = process² + gauge² + g² s² + 2 b11² s⁴, g = b1 + b12 f + 2 b11 ā (normal allowance); --compensate drops the force terms.
  subtune --simulate --parts 20 --arl-runs 20 --policy shewhart --compensate > comp.jsonl
  run check 'import math; assert near(rows[0]["sigma_mm"], math.sqrt(0.002**2 + 0.001**2), 1e-15), rows' < comp.jsonl
  assert_output "ok"
  printf '{"record":"model","b0":0.001,"b1":0.004,"b2":0.02,"b12":0.01,"b11":0.003,"b22":0.05}\n' > model.jsonl
  subtune --simulate --parts 20 --arl-runs 20 --policy shewhart --sim-model model.jsonl --allowance 1.5 --allowance-sd 0.3 --feed 0.25 > sim.jsonl
  run check 'import math
g = 0.004 + 0.01 * 0.25 + 2 * 0.003 * 1.5
want = math.sqrt(0.002**2 + 0.001**2 + g * g * 0.09 + 2 * 0.003**2 * 0.3**4)
assert near(rows[0]["sigma_mm"], want, 1e-12 * want), (rows, want)' < sim.jsonl
  assert_output "ok"
}

@test "--simulate: sub-tuning's ARLs (eq. 6 as printed) see --resolution against sigma (scaling both by 10 changes nothing; the floor changes the ARL)" {
  subtune --simulate --policy subtune --statistic paper --arl-runs 2000 --sigma 0.003 --resolution 0.01 > a.jsonl
  subtune --simulate --policy subtune --statistic paper --arl-runs 2000 --sigma 0.03 --resolution 0.1 > b.jsonl
  subtune --simulate --policy subtune --statistic paper --arl-runs 2000 --sigma 0.003 > c.jsonl
  run py 'import json
a, b, c = (json.loads(open(f).readline()) for f in ("a.jsonl", "b.jsonl", "c.jsonl"))
for k in ("arl0", "arl_shift", "arl_drift"):
    assert abs(a[k] - b[k]) <= 1e-9 * a[k], (k, a[k], b[k])
# r/sigma = 3.3: S_N is floored at 0.96 sigma, above most runs own spread, so alarms come later
assert a["arl0"] - c["arl0"] > 4 * (a["arl0_se"] ** 2 + c["arl0_se"] ** 2) ** 0.5, (a, c)
print("ok")'
  assert_output "ok"
}
