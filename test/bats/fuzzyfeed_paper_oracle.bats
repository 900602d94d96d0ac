#!/usr/bin/env bats
# fuzzyfeed against Stryczek & Orawczak (seed 001): the paper's Test 1
# findings and those after the modification of the formulas, as
# inequalities, on the simulated cut (E295, 0.4 mm/rev, 1 and 3 mm, 9 kW;
# fuzzyfeed(1), FIDELITY). The law itself is held against the paper's
# formulas by test_feed_override.cpp (a grid against
# test/oracle/fuzzyfeed_law.py) and fuzzyfeed.bats (streams).

bats_require_minimum_version 1.5.0

setup() {
  load test_helper
  cd "$BATS_TEST_TMPDIR"
}

# summarise ARGS...: one line per run of "fuzzyfeed --simulate --segments ARGS":
# the time ratio, then for 1 mm and for 3 mm the settled override (mean over
# the segments) and the largest oscillation.
summarise() {
  fuzzyfeed --simulate --segments "$@" | py '
import json, sys
rows = [json.loads(l) for l in sys.stdin]
segs, s = rows[:-1], rows[-1]
def of(depth, key, pick):
    return pick(r[key] for r in segs if r["depth"] == depth)
mean = lambda xs: (lambda v: sum(v) / len(v))(list(xs))
print(s["time_ratio"], of(1, "settled_override_pct", mean), of(1, "oscillation_pct", max),
      of(3, "settled_override_pct", mean), of(3, "oscillation_pct", max), of(1, "load_at_100_pct", max))'
}

@test "Test 1 and the modified law: the findings, as inequalities, for three noise seeds" {
  for seed in 1 2 3; do
    read -r ratio o1 osc1 o3 osc3 load1 < <(summarise --seed "$seed")
    # The paper's direction, with its figure as the bound (ours go further;
    # fuzzyfeed(1), FIDELITY, says why):
    # "When the cutting allowance was 1mm the drive load was about 25%": ours
    # is a third of the 3 mm cut's, well below M_z at the programmed feed.
    # "[it] set ... \$AC_OVR at approximately 145%": the override rises past it.
    # "theoretically, the process was 20% shorter": at least 20 %.
    # "oscillation of +-10%": at least +-10 where the load reaches M_z (3 mm).
    py "assert 25 <= $load1 < 40 and $o1 >= 145 and $ratio <= 0.8 and $osc3 >= 10, ($load1, $o1, $ratio, $osc3)"
    read -r ratio o1 osc1 o3 osc3 load1 < <(summarise --seed "$seed" --variant modified --k 0.1 --p 0.1 --d 25)
    # "Overregulation was eliminated": under +-2 points everywhere; still shorter.
    py "assert $osc1 < 2 and $osc3 < 2 and $ratio <= 0.8, ($osc1, $osc3, $ratio)"
  done
}

@test "the original law's oscillation and its absence under the modified one do not hang on the plant's constants" {
  for plant in "--ipo 0.004" "--ipo 0.012" "--kv 1000 --lag 0 --noise 0" "--cutting-speed 170"; do
    read -r ratio o1 osc1 o3 osc3 load1 < <(summarise $plant)
    py "assert $osc3 >= 10, ('$plant', $osc3)"
    read -r ratio o1 osc1 o3 osc3 load1 < <(summarise $plant --variant modified)
    py "assert $osc1 < 2 and $osc3 < 2, ('$plant', $osc1, $osc3)"
  done
}
