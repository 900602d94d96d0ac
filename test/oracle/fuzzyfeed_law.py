#!/usr/bin/env python3
"""Stryczek & Orawczak's feed-override law, written from the paper's text
(seed 001, "2. Methodology" and "3. Test results") for fuzzyfeed's tests,
independently of the C++:

  Step 1 (the correction coefficient), for M_a < M_z and M_a > M_z:
    (1) W_k = exp((-5/M_z^2)(M_a^2))
    (2) W_k = exp(-10/(1-M_z/100)(M_a/100-M_z/100)^2)
  Step 2 (the new programmed correction coefficient O_n from O_a):
    (3) O_n = 200 (O_a/200 + W_k - W_k O_a/200)      fuzzy disjunction, M_a < M_z
    (4) O_n = W_k O_a                                 fuzzy conjunction, M_a > M_z
  The modified formulas replace (1), (2) and (4):
    (5) W_k = k exp((-5/M_z^2)(M_a^2))
    (6) W_k = p exp(-10/(1 - M_z/100)(M_a/100 - M_z/100)^2) + (1 - p)
    (7) O_n = W_k (O_a - d) + d

The paper says nothing of M_a = M_z; fuzzyfeed(1) holds the override there
(W_k = 1, O_n = O_a), which is what (2)/(4) and (6)/(7) give as M_a
comes down to M_z, and so does this file. An optional floor (fuzzyfeed's
--min-override, 0 by default) bounds O_n from below.

  fuzzyfeed_law.py grid [--variant V] [--k K] [--p P] [--d D]  < "ma mz oa" lines
      prints "wk on" per line: one step from each triple
  fuzzyfeed_law.py stream [--variant V] [--mz MZ] [--k K] [--p P] [--d D]
                          [--initial-override O] [--min-override F] < records.jsonl
      prints "wk override" per record, the override carried from record to record
"""
import argparse
import json
import math
import sys


def coefficient(ma, mz, variant, k, p):
    """Step 1: W_k."""
    if ma < mz:
        w = math.exp((-5.0 / mz ** 2) * ma ** 2)                      # (1)
        return k * w if variant == "modified" else w                   # (5)
    if ma == mz:
        return 1.0
    w = math.exp(-10.0 / (1.0 - mz / 100.0) * (ma / 100.0 - mz / 100.0) ** 2)   # (2)
    return p * w + (1.0 - p) if variant == "modified" else w                     # (6)


def new_override(ma, mz, oa, wk, variant, d):
    """Step 2: O_n."""
    if ma < mz:
        return 200.0 * (oa / 200.0 + wk - wk * oa / 200.0)            # (3)
    if variant == "modified":
        return wk * (oa - d) + d                                       # (7)
    return wk * oa                                                     # (4)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=["grid", "stream"])
    ap.add_argument("--variant", default="original", choices=["original", "modified"])
    ap.add_argument("--mz", type=float, default=60.0)
    ap.add_argument("--k", type=float, default=0.1)
    ap.add_argument("--p", type=float, default=0.1)
    ap.add_argument("--d", type=float, default=25.0)
    ap.add_argument("--initial-override", type=float, default=100.0)
    ap.add_argument("--min-override", type=float, default=0.0)
    a = ap.parse_args()
    out = []
    if a.mode == "grid":
        for line in sys.stdin:
            if not line.strip():
                continue
            ma, mz, oa = (float(x) for x in line.split())
            wk = coefficient(ma, mz, a.variant, a.k, a.p)
            on = new_override(ma, mz, oa, wk, a.variant, a.d)
            out.append("%.17g %.17g" % (wk, min(200.0, max(a.min_override, on))))
    else:
        o = a.initial_override
        for line in sys.stdin:
            if not line.strip():
                continue
            ma = float(json.loads(line)["load"])
            wk = coefficient(ma, a.mz, a.variant, a.k, a.p)
            o = min(200.0, max(a.min_override, new_override(ma, a.mz, o, wk, a.variant, a.d)))
            out.append("%.17g %.17g" % (wk, o))
    sys.stdout.write("".join(line + "\n" for line in out))


main()
