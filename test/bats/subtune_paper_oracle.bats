#!/usr/bin/env bats
# subtune against what its paper prints (Georgiev, Chetrokov & Salapateva,
# ../shared/seeds/004_1585d7a9823158a8.txt), each check against
# test/oracle/subtune_paper.py or subtune_regression.py, both written from
# the paper's text (eq. 2-6 and the rules around them), or against hand values.
# The findings are held as inequalities. A test is skipped when an oracle
# exits 77 (SciPy missing).

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

# oracle SCRIPT ARGS... < input: test/oracle/SCRIPT, failing on any failed check.
oracle() {
  run /usr/bin/python3 "$TOOLKIT_ROOT/test/oracle/$1" "${@:2}"
  [ "$status" -ne 77 ] || skip "$output"
  echo "$1 ${*:2}: $output"
  [ "$status" -eq 0 ]
}

# noise FILE PARTS SEED: independent N(0, 1) sizes, one per line.
noise() {
  py 'import sys
import numpy as np
np.savetxt(sys.argv[1], np.random.default_rng(int(sys.argv[3])).standard_normal(int(sys.argv[2])), fmt="%.17g")' "$@"
}

@test "eq. (3)-(6): every part of a drifting run as the paper's equations give it, with the printed statistic and with the default" {
  # 400 parts: 2 um of wear per part, 5 um of noise, 40 mm.
  py 'import numpy as np
rng = np.random.default_rng(4)
np.savetxt("wear.txt", 40 + 0.002 * np.arange(1, 401) + rng.normal(0, 0.005, 400), fmt="%.6f")'
  for statistic in paper slope; do
    subtune --statistic "$statistic" wear.txt > out.jsonl
    oracle subtune_regression.py --statistic "$statistic" < out.jsonl
    # the drift is seen: runs restart, both decisions occur
    [ "$(grep -c '"decision":"subtune"' out.jsonl)" -ge 10 ]
    [ "$(grep -c '"decision":"none"' out.jsonl)" -ge 10 ]
  done
}

@test "eq. (6)'s real level: a first test at N = 4 sub-tunes on pure noise about half the time (0.51 at alpha 0.05); the default's is alpha" {
  noise noise.txt 30000 1
  subtune --statistic paper noise.txt > paper.jsonl
  oracle subtune_paper.py level --statistic paper --alpha 0.05 --min-parts 4 < paper.jsonl
  # the default (slope) at alpha 0.5, so that runs end and many first tests occur
  subtune --alpha 0.5 noise.txt > slope.jsonl
  oracle subtune_paper.py level --statistic slope --alpha 0.5 --min-parts 4 < slope.jsonl
  # eq. (6) from the tenth part: 0.444
  subtune --statistic paper --min-parts 10 noise.txt > paper10.jsonl
  oracle subtune_paper.py level --statistic paper --alpha 0.05 --min-parts 10 < paper10.jsonl
}

@test "the correction of value and sign dA and the restart: a lathe wearing 1 um per part without noise cycles 40.001 .. 40.004" {
  for statistic in paper slope; do
    subtune --simulate --policy subtune --statistic "$statistic" --parts 40 --wear 0.001 --thermal 0 --allowance-sd 0 \
      --process-sd 0 --gauge-sd 0 --sigma 0.003 --arl-runs 2 --trace trace.jsonl > /dev/null
    oracle subtune_paper.py sawtooth --nominal 40 --wear 0.001 < trace.jsonl
    assert_output --partial "40 parts in the cycle"
  done
}

@test "eq. (2) and its two uses: the set-up correction -y at f = const, the feed for y = const (A = const without sub-tuning)" {
  local c=0.003,0.006,0.02,0.012,0.0008,0.04
  printf '{"a":%s}\n' 0.3 0.6 0.9 1.2 1.5 2.0 2.5 3.0 4.0 > blanks.jsonl
  subtune feed --coefficients "$c" --target 0.015 -q blanks.jsonl > feed.jsonl
  subtune correct --coefficients "$c" --feed 0.2 blanks.jsonl > correct.jsonl
  oracle subtune_paper.py approaches "$c" 0.015 0.2 0.05 0.5 feed.jsonl correct.jsonl
  # the finding behind the second use: with the feed chosen per blank the
  # predicted error is the same for every solved blank; at a fixed feed it
  # spreads with the allowance
  run check 'import json
fed = [r for r in rows if r["feed_status"] == "solved"]
corr = [json.loads(l) for l in open("correct.jsonl")]
assert len(fed) >= 4, fed
assert max(r["predicted_error"] for r in fed) - min(r["predicted_error"] for r in fed) <= 1e-12
assert max(r["predicted_error"] for r in corr) - min(r["predicted_error"] for r in corr) > 0.01, corr' < feed.jsonl
  assert_output "ok"
}

@test "the conclusion, 'improve precision': sub-tuning cuts the rms deviation of a wearing lathe; eq. (6) alone worsens a stable one" {
  local sim=(--simulate --arl-runs 2 --parts 1000)
  subtune "${sim[@]}" --policy none > none.jsonl
  subtune "${sim[@]}" --policy subtune > slope.jsonl
  subtune "${sim[@]}" --policy subtune --statistic paper > paper.jsonl
  subtune "${sim[@]}" --policy none --wear 0 --thermal 0 > none_stable.jsonl
  subtune "${sim[@]}" --policy subtune --wear 0 --thermal 0 > slope_stable.jsonl
  subtune "${sim[@]}" --policy subtune --statistic paper --wear 0 --thermal 0 > paper_stable.jsonl
  run py 'import json
r = {name: json.loads(open(name + ".jsonl").readline()) for name in ("none", "slope", "paper", "none_stable", "slope_stable", "paper_stable")}
rms = {k: v["rms_deviation_mm"] for k, v in r.items()}
print(rms)
# wear and warm-up: both tests at least halve the rms deviation of no control
assert rms["slope"] < rms["none"] / 2 and rms["paper"] < rms["none"] / 2, rms
# a stable lathe: eq. (6) corrects on noise (over 100 of 1000 parts) and the
# corrections back to the run start add up; the default leaves it alone
assert r["paper_stable"]["corrections"] > 100 and rms["paper_stable"] > 3 * rms["none_stable"], r["paper_stable"]
assert r["slope_stable"]["corrections"] <= 5 and rms["slope_stable"] < 1.5 * rms["none_stable"], r["slope_stable"]
print("ok")'
  echo "$output"
  assert_line "ok"
}
