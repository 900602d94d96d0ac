#!/usr/bin/python3
"""The seed's invasion experiment (seed 003, section 6, Tables 2-3) in
closed form, written from the paper's text, not from dxf2region's code.

The operator drives the tool at feed V straight at a long straight edge of
the profile, at an angle theta to its normal (uniform within +-max_angle),
so the distance falls at V cos(theta). The control reads the position every
P seconds; the first reading closer than the tolerance T orders the stop,
which takes effect L seconds later. The reading falls anywhere within the
last period's travel, so the tool stops at T - V cos(theta) (L + u P), u
uniform on [0, 1). A stroke succeeds when that is not negative (the paper:
"the prohibited region is not trespassed"); the under-cut is that distance
("the achieved position is outside the profile and distant ... from the
profile"), averaged over the successes.

    invasion_model.py predict V T L P [MAX_ANGLE]   -> success under-cut
    invasion_model.py fit                           -> L and P that fit Table 2 (a)'s successes, per speed
                                                       and for both speeds, in time and in travel
"""
import math
import sys

import numpy as np

# Table 2 (a), external machining of a triangle: V, T, attempts, successes, mean under-cut (None: no success).
TABLE_2A = [
    (12, 1.0, 17, 0, None), (12, 2.0, 17, 3, 0.15), (12, 3.0, 17, 11, 0.54), (12, 4.0, 18, 16, 1.25), (12, 5.0, 20, 20, 2.50),
    (18, 1.0, 15, 1, 0.50), (18, 2.0, 19, 4, 0.25), (18, 3.0, 18, 14, 0.68), (18, 4.0, 19, 17, 1.15), (18, 5.0, 20, 19, 2.63),
]


def outcome(v, t, latency, period, max_angle_deg=60.0, nodes=801):
    """(success probability, mean under-cut of the successes, its variance):
    the integral over u in closed form, over theta by the midpoint rule."""
    half = math.radians(max_angle_deg)
    theta = (np.arange(nodes) + 0.5) / nodes * 2 * half - half
    speed = v * np.cos(theta)
    a, b = speed * latency, speed * period  # the stop lands at t - a - b u
    with np.errstate(divide="ignore", invalid="ignore"):
        ustar = np.clip(np.where(b > 0, (t - a) / b, np.where(t >= a, 1.0, 0.0)), 0.0, 1.0)
        first = (t - a) * ustar - b * ustar ** 2 / 2
        second = np.where(b > 0, ((t - a) ** 3 - (t - a - b * ustar) ** 3) / (3 * b), (t - a) ** 2 * ustar)
    success = ustar.mean()
    if success <= 0:
        return 0.0, float("nan"), float("nan")
    mean = first.mean() / success
    return float(success), float(mean), float(max(second.mean() / success - mean ** 2, 1e-6))


def success_grid(rows, latency, period, max_angle_deg=60.0, nodes=201):
    """Success probabilities of `rows` over arrays of latency and period
    (broadcast against each other): one array per row."""
    half = math.radians(max_angle_deg)
    cosine = np.cos((np.arange(nodes) + 0.5) / nodes * 2 * half - half)
    latency, period = np.asarray(latency, float)[..., None], np.asarray(period, float)[..., None]
    out = []
    for v, t, *_ in rows:
        a, b = v * cosine * latency, v * cosine * period
        out.append(np.clip((t - a) / b, 0.0, 1.0).mean(-1))
    return out


def deviance(rows, probabilities):
    """-2 log likelihood of the rows' successes out of their attempts."""
    total = 0.0
    for (v, t, n, s, _), p in zip(rows, probabilities):
        p = np.clip(p, 1e-4, 1 - 1e-4)
        total = total - 2 * (s * np.log(p) + (n - s) * np.log(1 - p))
    return total


def best(rows, travel):
    """The latency and period (seconds, or mm of travel when `travel`) that
    fit the rows' success counts best: on a coarse grid, then on a grid a
    quarter as fine about its best point. (deviance, latency, period)."""
    step = (0.025, 0.025) if travel else (0.0025, 0.0025)
    ranges = ((0.0, 6.0), (0.025, 8.0)) if travel else ((0.0, 0.6), (0.0025, 0.8))  # latency, period

    def search(latencies, periods):
        grid_l, grid_p = np.meshgrid(latencies, periods, indexing="ij")
        total = 0.0
        for row in rows:  # the same travel is a time inversely proportional to the feed
            scale = 1.0 / row[0] if travel else 1.0
            total = total + deviance([row], success_grid([row], grid_l * scale, grid_p * scale, nodes=101))
        i, j = np.unravel_index(np.argmin(total), total.shape)
        return float(total[i, j]), float(latencies[i]), float(periods[j])

    coarse = [np.arange(low, high + 1e-9, 4 * k) for (low, high), k in zip(ranges, step)]
    _, latency, period = search(*coarse)
    fine = [np.arange(max(low, centre - 8 * k), min(high, centre + 8 * k) + 1e-9, k)
            for (low, high), k, centre in zip(ranges, step, (latency, period))]
    return search(*fine)


def fit():
    """Table 2 (a)'s success counts: each speed alone, then both speeds
    under one delay in time, then under one delay in travel; the
    likelihood ratio of each joint fit against the separate ones (2
    degrees of freedom)."""
    from scipy.stats import chi2
    slow, fast = [r for r in TABLE_2A if r[0] == 12], [r for r in TABLE_2A if r[0] == 18]
    separate = 0.0
    for label, rows in (("12 mm/s", slow), ("18 mm/s", fast)):
        d, latency, period = best(rows, False)
        separate += d
        print(f"{label}: latency {latency:.4f} s, period {period:.4f} s (deviance {d:.2f})")
    for label, travel, unit in (("both, time", False, "s"), ("both, travel", True, "mm")):
        d, latency, period = best(TABLE_2A, travel)
        ratio = d - separate
        print(f"{label}: latency {latency:.4f} {unit}, period {period:.4f} {unit} (deviance {d:.2f}, "
              f"likelihood ratio {ratio:.2f}, p {chi2.sf(ratio, 2):.2g})")


def main(argv):
    if len(argv) >= 5 and argv[0] == "predict":
        v, t, latency, period = map(float, argv[1:5])
        angle = float(argv[5]) if len(argv) > 5 else 60.0
        p, mean, _ = outcome(v, t, latency, period, angle)
        print(f"{p:.6f} {mean:.6f}")
    elif argv[:1] == ["fit"]:
        fit()
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
