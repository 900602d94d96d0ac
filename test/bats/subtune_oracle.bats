#!/usr/bin/env bats
# subtune against independent oracles, no figure captured from its own output:
#  - test/oracle/subtune_regression.py recomputes every part's regression,
#    t, t_crit, decision, correction, offset, run and n with SciPy/NumPy;
#  - Student t critical values against printed tables;
#  - test/oracle/spc_arl.py: Shewhart (exact), EWMA and CUSUM ARLs by Brook &
#    Evans' Markov chains, and the published ARLs, against --simulate's
#    Monte-Carlo ARLs within 4 of their standard errors;
#  - test/oracle/force_model_lstsq.py (numpy lstsq) against 'subtune model';
#    brute-force scans of y(a, f) - target against 'subtune feed'; -y against
#    'subtune correct'.
# The streams and the calibration are fixtures written by
# test/fixtures/subtune/make_fixtures.py (drift + noise; a known model + noise).
# Skipped when SciPy is missing.

bats_require_minimum_version 1.5.0

setup_file() {
  /usr/bin/python3 -c 'import scipy.stats, scipy.optimize' 2>/dev/null || skip "SciPy (python3-scipy) is not installed"
}

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
  SUB="$FIXTURES/subtune"
  ORACLE="$TOOLKIT_ROOT/test/oracle"
}

# regressions < CASES: each line of CASES is "FILE [OPTIONS...]": subtune
# with OPTIONS on FILE, then one subtune_regression.py run (SciPy starts
# once, not once per case) checks every output against the same options;
# fails on any mismatch.
regressions() {
  local file options i=0
  : > cases.txt
  while read -r file options; do
    i=$((i + 1))
    local out="out$i-$(basename "$file").jsonl"
    # shellcheck disable=SC2086 # the options are separate words
    subtune $options "$file" > "$out" || { echo "subtune $options $file failed"; return 1; }
    echo "$out $options" >> cases.txt
  done
  [ "$i" -gt 0 ] || { echo "no cases"; return 1; }
  run /usr/bin/python3 "$ORACLE/subtune_regression.py" --cases cases.txt
  [ "$status" -ne 77 ] || skip "$output"
  echo "$output"
  [ "$status" -eq 0 ]
}

# expect_t_crit FILE "N:VALUE ..." : at each N, t_crit within 1e-6 of the table VALUE.
expect_t_crit() {
  py 'import json, sys
rows = {}
for line in open(sys.argv[1]):
    r = json.loads(line)
    rows.setdefault(r["n"], r)
bad = 0
for pair in sys.argv[2].split():
    n, want = pair.split(":")
    r = rows[int(n)]
    ok = r["decision"] == "none" and r["t_crit"] is not None and abs(r["t_crit"] - float(want)) <= 1e-6
    bad += not ok
    print(("ok" if ok else "FAIL"), "n", n, "df", r["df"], "t_crit", r["t_crit"], "table", want, r["decision"])
sys.exit(1 if bad else 0)' "$1" "$2"
}

@test "(a) three 300-part streams (wear, thermal growth, no drift) x 9 option sets: every part recomputed by SciPy" {
  for file in "$SUB/wear.txt" "$SUB/thermal.csv" "$SUB/flat.jsonl"; do
    printf "$file %s\n" "" "--statistic paper" "--alternative greater --statistic paper" "--alternative less" \
      "--correct-to nominal --nominal 40 --statistic paper" "--resolution 0.005 --statistic paper" \
      "--alpha 0.01 --min-parts 6 --statistic paper" "--lower 39.995 --upper 40.02" "--min-parts 3 --alpha 0.1"
  done > cases.in
  regressions < cases.in
  [ "$(grep -c ' records, ' <<< "$output")" -eq 27 ]
}

@test "(a) the streams exercise the test: runs restart, both decisions occur, the drifting ones sub-tune more" {
  subtune --statistic paper "$SUB/wear.txt" > wear.jsonl
  subtune "$SUB/flat.jsonl" > flat.jsonl
  subtune "$SUB/wear.txt" > wear_slope.jsonl
  run py 'import json
def load(name):
    return [json.loads(l) for l in open(name)]
wear, flat, wear_slope = load("wear.jsonl"), load("flat.jsonl"), load("wear_slope.jsonl")
count = lambda rows, d: sum(r["decision"] == d for r in rows)
assert count(wear, "subtune") >= 10 and count(wear, "none") >= 10, (count(wear, "subtune"), count(wear, "none"))
assert max(r["run"] for r in wear) == count(wear, "subtune") + (wear[-1]["decision"] != "subtune")
# the default slope test at 5 %: few false alarms without drift, more with wear
assert count(flat, "subtune") <= 6, count(flat, "subtune")
assert count(wear_slope, "subtune") > 2 * count(flat, "subtune"), (count(wear_slope, "subtune"), count(flat, "subtune"))
print("ok")'
  assert_output "ok"
}

@test "(a) sizes near the +-1e6 mm bound and near the 1e-100 mm floor: as SciPy on scaled sizes" {
  py 'import random
random.seed(5)
for name, scale in (("big", 8e5), ("small", 2e-100)):
    with open(name + ".txt", "w") as out:
        for i in range(1, 61):
            out.write(repr((1 + 0.002 * i + random.gauss(0, 0.01)) * scale) + "\n")'
  printf '%s\n' big.txt small.txt "small.txt --statistic paper" > cases.in
  regressions < cases.in
}

@test "(b) t_crit against the printed Student t table (two-sided 5 %, eq. (6)'s df 2(N-1)) for N = 4, 5, 6, 8, 10" {
  # A zig-zag that never reaches significance: t <= 1.83 at every N.
  printf '%s\n' 10.000 10.001 10.001 10.000 10.000 10.001 10.001 10.000 10.000 10.001 > zigzag.txt
  subtune --statistic paper zigzag.txt > zigzag.jsonl
  run expect_t_crit zigzag.jsonl "4:2.446912 5:2.306004 6:2.228139 8:2.144787 10:2.100922"
  echo "$output"
  assert_success
  # The regression oracle agrees on every record.
  echo "zigzag.txt --statistic paper" > cases.in
  regressions < cases.in
}

@test "(b) t_crit tables: the default slope statistic df N-2 (2.776445 ... 4.302653); eq. (6) one-sided 5 %, two-sided 1 %" {
  printf '12.5\n%.0s' $(seq 12) > constant.txt
  subtune --min-parts 4 constant.txt > slope.jsonl
  run expect_t_crit slope.jsonl "4:4.302653 5:3.182446 6:2.776445 7:2.570582 8:2.446912 9:2.364624 10:2.306004 11:2.262157 12:2.228139"
  echo "$output"
  assert_success
  subtune --statistic paper --alternative greater constant.txt > greater.jsonl
  run expect_t_crit greater.jsonl "4:1.943180 5:1.859548 6:1.812461 8:1.761310 10:1.734064"
  echo "$output"
  assert_success
  subtune --statistic paper --alternative less constant.txt > less.jsonl
  run expect_t_crit less.jsonl "4:1.943180 10:1.734064"
  assert_success
  subtune --statistic paper --alpha 0.01 constant.txt > one_percent.jsonl
  run expect_t_crit one_percent.jsonl "4:3.707428 6:3.169273"
  echo "$output"
  assert_success
}

@test "(c) spc_arl.py reproduces the published ARLs (Shewhart 370.4/43.9, CUSUM 465/10.4, SAS EWMAARL 11.154267)" {
  run /usr/bin/python3 "$ORACLE/spc_arl.py" selfcheck
  [ "$status" -ne 77 ] || skip "$output"
  echo "$output"
  assert_success
  assert_output --partial "EWMA lam 0.2 L 3 at 0 sigma"
}

@test "(c) --simulate ARLs of the default charts: within 4 se of the Markov chains and of the published values" {
  # --arl-cap 40000 keeps 20,000 runs within the 3e9 parts a run may
  # imply; with ARL0s of 370 to 465 no run comes near it.
  for pol in shewhart ewma cusum; do
    subtune --simulate --policy "$pol" --arl-runs 20000 --arl-cap 40000 --seed 7
  done > arl.jsonl
  run /usr/bin/python3 "$ORACLE/spc_arl.py" compare --published < arl.jsonl
  [ "$status" -ne 77 ] || skip "$output"
  echo "$output"
  assert_success
  [ "$(grep -c '^ok' <<< "$output")" -eq 13 ]  # 9 chain checks + 4 published
}

@test "(c) --simulate ARLs with other chart settings, a 0.5 sigma step and a 0.05 sigma/part drift" {
  local opts=(--shewhart-l 2.5 --ewma-lambda 0.1 --ewma-l 2.7 --cusum-k 0.25 --cusum-h 8 --shift 0.5 --drift 0.05)
  for pol in shewhart ewma cusum; do
    subtune --simulate --policy "$pol" --arl-runs 20000 --arl-cap 40000 --seed 3 "${opts[@]}"
  done > arl.jsonl
  run /usr/bin/python3 "$ORACLE/spc_arl.py" compare "${opts[@]}" < arl.jsonl
  [ "$status" -ne 77 ] || skip "$output"
  echo "$output"
  assert_success
  [ "$(grep -c '^ok' <<< "$output")" -eq 9 ]
}

@test "(d) subtune model on 24 noisy calibration points: coefficients and r2 as numpy lstsq, the derived figures by their formulas" {
  subtune model "$SUB/calibration.jsonl" > model.json
  /usr/bin/python3 "$ORACLE/force_model_lstsq.py" < "$SUB/calibration.jsonl" > lstsq.json
  subtune model --residuals "$SUB/calibration.jsonl" > residuals.jsonl
  run py 'import json, math
import numpy as np
m = json.load(open("model.json"))
ref = json.load(open("lstsq.json"))
names = ["b0", "b1", "b2", "b12", "b11", "b22"]
big = max(abs(ref[k]) for k in names)
for k in names:
    assert abs(m[k] - ref[k]) <= 1e-9 * big, (k, m[k], ref[k])
assert abs(m["r2"] - ref["r2"]) <= 1e-10, (m["r2"], ref["r2"])
rows = [json.loads(l) for l in open("'"$SUB/calibration.jsonl"'")]
n, p = len(rows), 6
a, f, y = (np.array([r[k] for r in rows]) for k in "afy")
X = np.column_stack([np.ones(n), a, f, a * f, a * a, f * f])
beta = np.array([ref[k] for k in names])
fitted = X @ beta
sse = float(np.sum((y - fitted) ** 2))
assert m["record"] == "model" and m["points"] == n, m
assert abs(m["adjusted_r2"] - (1 - (1 - ref["r2"]) * (n - 1) / (n - p))) <= 1e-10, m["adjusted_r2"]
assert abs(m["residual_sd"] - math.sqrt(sse / (n - p))) <= 1e-9 * math.sqrt(sse / (n - p)), m["residual_sd"]
assert m["condition"] >= 1, m["condition"]
# the true model (make_fixtures.py) is recovered within the noise
true = [0.002, 0.008, 0.03, 0.01, 0.001, 0.05]
assert 0.9 < m["r2"] <= 1 and 0.0002 < m["residual_sd"] < 0.0008, m
res = [json.loads(l) for l in open("residuals.jsonl")]
assert len(res) == n + 1 and res[-1] == m, (len(res), res[-1])
for r, row, fit in zip(res, rows, fitted):
    assert r["record"] == "point" and (r["a"], r["f"], r["y"]) == (row["a"], row["f"], row["y"]), r
    assert abs(r["fitted"] - fit) <= 1e-12 and abs(r["residual"] - (row["y"] - fit)) <= 1e-12, (r, fit)
print("ok")'
  echo "$output"
  assert_output "ok"
}

@test "(d) subtune model on a wider, unscaled design (5 feeds x 6 depths, 60 points with repeats)" {
  py 'import json, random
random.seed(11)
with open("wide.jsonl", "w") as out:
    for rep in range(2):
        for a in (0.2, 0.8, 1.5, 2.5, 3.5, 5.0):
            for f in (0.05, 0.12, 0.2, 0.35, 0.5):
                y = -0.004 + 0.011 * a + 0.02 * f + 0.03 * a * f - 0.0007 * a * a + 0.09 * f * f
                out.write(json.dumps({"a": a, "f": f, "y": y + random.gauss(0, 0.001)}) + "\n")'
  subtune model wide.jsonl > model.json
  /usr/bin/python3 "$ORACLE/force_model_lstsq.py" < wide.jsonl > lstsq.json
  run py 'import json
m, ref = json.load(open("model.json")), json.load(open("lstsq.json"))
names = ["b0", "b1", "b2", "b12", "b11", "b22"]
big = max(abs(ref[k]) for k in names)
bad = [(k, m[k], ref[k]) for k in names if abs(m[k] - ref[k]) > 1e-9 * big]
assert not bad and abs(m["r2"] - ref["r2"]) <= 1e-10 and m["points"] == 60, (bad, m)
print("ok")'
  assert_output "ok"
}

# feed_oracle MODEL_JSON TARGET FMIN FMAX < subtune feed output: a brute-force
# scan of y(a, f) - target on 400001 feeds, the largest sign change refined by
# brentq; error_min/max as the scan's extremes (and the vertex when inside).
feed_oracle() {
  py 'import json, sys
import numpy as np
from scipy.optimize import brentq
m = json.loads(sys.argv[1])
target, fmin, fmax = map(float, sys.argv[2:5])
b0, b1, b2, b12, b11, b22 = (m[k] for k in ["b0", "b1", "b2", "b12", "b11", "b22"])
y = lambda a, f: b0 + b1 * a + b2 * f + b12 * a * f + b11 * a * a + b22 * f * f
fs = np.linspace(fmin, fmax, 400001)
bad = solved = none = 0
for line in sys.stdin:
    r = json.loads(line)
    a = float(r["a"])
    ys = y(a, fs)
    cand = [y(a, fmin), y(a, fmax)]
    if b22 != 0:
        vertex = -(b2 + b12 * a) / (2 * b22)
        if fmin < vertex < fmax:
            cand.append(y(a, vertex))
    lo, hi = min(min(cand), ys.min()), max(max(cand), ys.max())
    g = ys - target
    g[np.abs(g) <= 1e-12 * max(1.0, abs(target))] = 0.0  # on the target up to rounding
    root = None
    change = np.nonzero(g[:-1] * g[1:] <= 0)[0]
    if change.size:
        k = change[-1]
        if g[k + 1] == 0:
            root = fs[k + 1]
        elif g[k] == 0:
            root = fs[k]
        else:
            root = brentq(lambda f: y(a, f) - target, fs[k], fs[k + 1], xtol=1e-15)
    ok = abs(r["error_min"] - lo) <= 1e-12 and abs(r["error_max"] - hi) <= 1e-12
    if root is None:
        none += 1
        ok = ok and r["feed_status"] == "none" and r["feed"] is None and r["predicted_error"] is None
    else:
        solved += 1
        # At a tangency (a double root) the root is only defined to ~sqrt(eps):
        # there the feed of the tool must hit the target and lie within 1e-5.
        close = abs(r["feed"] - root) <= 1e-9 or (
            abs(y(a, r["feed"]) - target) <= 1e-12 and abs(r["feed"] - root) <= 1e-5)
        ok = ok and r["feed_status"] == "solved" and close and abs(r["predicted_error"] - target) <= 1e-12
    bad += not ok
    if not ok:
        print("FAIL a", a, "tool", r, "oracle feed", root, "range", lo, hi)
print(f"{solved} solved, {none} none, {bad} mismatches")
sys.exit(1 if bad else 0)' "$@"
}

@test "(e) subtune feed with the fitted model: the largest feed with y = target, as a brute-force scan finds it" {
  subtune model "$SUB/calibration.jsonl" > model.json
  run --separate-stderr subtune feed --model model.json --target 0.03 "$SUB/allowances.jsonl"
  assert_success
  echo "$output" > feed.jsonl
  [[ "$stderr" == *"8 workpiece(s) have no feed"* ]]
  [ "$(grep -c . <<< "$stderr")" -eq 1 ]
  run feed_oracle "$(cat model.json)" 0.03 0.05 0.5 < feed.jsonl
  echo "$output"
  assert_success
  assert_output --partial "12 solved, 8 none"
  # the ids pass through
  [ "$(json-field id < feed.jsonl | head -1)" = W01 ]
  # all solved: no warning
  run --separate-stderr subtune feed --model model.json --target 0.03 --feed-min 0.1 --feed-max 0.3 <(printf '{"a":1.5}\n{"a":1.8}\n')
  assert_success
  [ -z "$stderr" ]
  echo "$output" | feed_oracle "$(cat model.json)" 0.03 0.1 0.3
}

@test "(e) subtune feed --coefficients: two roots in range (the larger wins), a tangency, none, a falling error on a narrower range" {
  local c
  printf '{"a":%s}\n' 0.1 0.3 0.5 0.75 1 1.25 1.5 2 3 > a.jsonl
  # y = 0.03 + 0.01 a - 0.3 f + f^2: a U in f with its vertex at f = 0.15
  # (at a = 1.25 the vertex touches the target 0.02: a double root)
  c='{"b0":0.03,"b1":0.01,"b2":-0.3,"b12":0,"b11":0,"b22":1.0}'
  subtune feed --coefficients 0.03,0.01,-0.3,0,0,1.0 --target 0.02 -q a.jsonl > u.jsonl
  run feed_oracle "$c" 0.02 0.05 0.5 < u.jsonl
  echo "$output"
  assert_success
  assert_output --partial "6 solved, 3 none, 0 mismatches"
  # by hand at a = 0.5: f^2 - 0.3 f + 0.015 = 0, f = (0.3 + sqrt(0.03)) / 2 = 0.2366025
  [ "$(head -3 u.jsonl | tail -1 | json-field feed | cut -c1-8)" = 0.236602 ]
  # a falling error with an interaction term
  c='{"b0":0.06,"b1":0.004,"b2":-0.05,"b12":-0.01,"b11":0.0005,"b22":-0.08}'
  subtune feed --coefficients 0.06,0.004,-0.05,-0.01,0.0005,-0.08 --target 0.035 --feed-min 0.08 --feed-max 0.45 -q a.jsonl > down.jsonl
  run feed_oracle "$c" 0.035 0.08 0.45 < down.jsonl
  echo "$output"
  assert_success
  assert_output --partial "9 solved, 0 none, 0 mismatches"
}

@test "(e) subtune correct: predicted_error = y(a, f) and correction = -y, f from --feed or the record" {
  subtune model "$SUB/calibration.jsonl" > model.json
  subtune correct --model model.json --feed 0.2 "$SUB/allowances.jsonl" > corr.jsonl
  subtune correct --coefficients 0.002,0.008,0.03,0.01,0.001,0.05 --feed 0.25 "$SUB/allowances.jsonl" > corr2.jsonl
  run py 'import json
def check(out, m, feed):
    rows = [json.loads(l) for l in open(out)]
    src = [json.loads(l) for l in open("'"$SUB/allowances.jsonl"'")]
    assert len(rows) == len(src) == 20
    for r, s in zip(rows, src):
        a, f = s["a"], s.get("f", feed)
        y = m["b0"] + m["b1"] * a + m["b2"] * f + m["b12"] * a * f + m["b11"] * a * a + m["b22"] * f * f
        assert r["id"] == s["id"] and abs(r["predicted_error"] - y) <= 1e-15 and abs(r["correction"] + y) <= 1e-15, (r, y)
check("corr.jsonl", json.load(open("model.json")), 0.2)
check("corr2.jsonl", dict(zip(["b0", "b1", "b2", "b12", "b11", "b22"], [0.002, 0.008, 0.03, 0.01, 0.001, 0.05])), 0.25)
print("ok")'
  echo "$output"
  assert_output "ok"
}

@test "(c) eq. (6)'s in-control ARL (about 6 parts at alpha 0.05): the tool's Monte Carlo against one in NumPy" {
  # The procedure from its definition: from N = 4 on, the least-squares line
  # over the run, S_N^2 = SSE/(N - 1), t = N|b|/S_N sqrt(N/2) against the
  # two-sided 5 % point at 2(N - 1) df; the run length is the first N where t exceeds it.
  subtune --simulate --policy subtune --statistic paper --parts 10 --arl-runs 20000 --arl-cap 40000 > sub.jsonl
  run py '
import json, math
import numpy as np
from scipy import stats
r = json.loads(open("sub.jsonl").readline())
rng = np.random.default_rng(7)
runs, lengths, crit = 10000, [], {}
for _ in range(runs):
    y = []
    while True:
        y.append(rng.standard_normal())
        n = len(y)
        if n < 4:
            continue
        i = np.arange(1, n + 1)
        b, a = np.polyfit(i, y, 1)
        s = math.sqrt(float(((np.array(y) - (a + b * i)) ** 2).sum()) / (n - 1))
        k = 2 * (n - 1)
        if k not in crit:
            crit[k] = stats.t.ppf(0.975, k)
        if n * abs(b) / s * math.sqrt(n / 2) > crit[k]:
            lengths.append(n)
            break
m, se = np.mean(lengths), np.std(lengths, ddof=1) / math.sqrt(runs)
assert abs(r["arl0"] - m) < 4 * math.hypot(se, r["arl0_se"]), (r["arl0"], r["arl0_se"], m, se)
print("ok", round(m, 3), r["arl0"])'
  echo "$output"
  assert_output --regexp '^ok '
}
