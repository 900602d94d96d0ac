#!/usr/bin/python3
"""Independent oracle for tnorm-bench eval: Könczöl & Gál's line-follower
controller written from the paper's text (seed 000, lines 507-810) and no
code of this project.

  Sensors left, mid, right; 10-bit LIGHT {-1, 0, 100, 700}, DARK {100, 700,
  1024, 1025}; 12-bit LIGHT {-1, 0, 396, 3135}, DARK {396, 3135, 4096, 4097}.
  Motor terms STOP {-10, 0, 0, 10}, FORWARD_MAX {60, 75, 80, 85}, FORWARD
  {45, 55, 65, 75}, BACKWARD {-80, -75, -70, -60}, BACKWARD_MAX {-90, -85,
  -80, -70}, each corner times the speed factor; BACKWARD_SLOWLY is not
  printed and comes from the command line.
  Rules for the left motor (sensors left, mid, right): R1 LLL STOP, R2 LLD
  FORWARD_MAX, R3 LDD FORWARD, R4 LDL FORWARD, R5 DDL BACKWARD, R6 DLL
  BACKWARD_MAX, R7 DDD BACKWARD_SLOWLY; the right motor swaps the left and
  right sensors.
  Rule activation: the paper's three-input t-norms, eq. (2), (4), (6), (8),
  (10), (12), written out as printed. Mamdani: each consequent clipped at
  its rule's activation, aggregated by maximum, centre of gravity of the
  aggregate (integrated on a fine grid, trapezoid rule).

Usage: line_follower.py --tnorm NAME [--adc 10|12] [--speed-factor K]
       [--backward-slowly A,B,C,D] < CSV(left,mid,right)
prints CSV left,mid,right,left_motor,right_motor (empty when no rule fires).
"""
import argparse
import csv
import math
import sys

import numpy as np

SENSOR_TERMS = {
    10: {"L": (-1, 0, 100, 700), "D": (100, 700, 1024, 1025)},
    12: {"L": (-1, 0, 396, 3135), "D": (396, 3135, 4096, 4097)},
}
MOTOR_TERMS = {
    "STOP": (-10, 0, 0, 10),
    "FORWARD_MAX": (60, 75, 80, 85),
    "FORWARD": (45, 55, 65, 75),
    "BACKWARD": (-80, -75, -70, -60),
    "BACKWARD_MAX": (-90, -85, -80, -70),
}
RULES = [  # (left, mid, right) -> left motor
    ("LLL", "STOP"),
    ("LLD", "FORWARD_MAX"),
    ("LDD", "FORWARD"),
    ("LDL", "FORWARD"),
    ("DDL", "BACKWARD"),
    ("DLL", "BACKWARD_MAX"),
    ("DDD", "BACKWARD_SLOWLY"),
]


def trapezoid(x, a, b, c, d):
    """Height-1 trapezoid, support [a, d], core [b, c]; works on arrays."""
    x = np.asarray(x, dtype=float)
    rise = np.clip((x - a) / (b - a), 0, 1) if b > a else (x >= a).astype(float)
    fall = np.clip((d - x) / (d - c), 0, 1) if d > c else (x <= d).astype(float)
    return np.minimum(rise, fall)


def t_three(name, m1, m2, m3):
    """The paper's three-input forms."""
    if name == "minimum":  # eq. (2)
        return min(m1, m2, m3)
    if name == "product":  # eq. (4)
        return m1 * m2 * m3
    if name == "drastic":  # eq. (6)
        if m2 == 1 and m3 == 1:
            return m1
        if m1 == 1 and m3 == 1:
            return m2
        if m1 == 1 and m2 == 1:
            return m3
        return 0.0
    if name == "lukasiewicz":  # eq. (8)
        return max(0.0, max(0.0, m1 + m2 - 1) + m3 - 1)
    if name == "trigonometric":  # eq. (10)
        h = math.pi / 2
        return 2 / math.pi * math.asin(math.sin(m1 * h) * math.sin(m2 * h) * math.sin(m3 * h))
    if name == "hamacher":  # eq. (12); its 0/0 (two zeros) is the t-norm's 0
        den = m1 * m2 + m1 * m3 + m2 * m3 - 2 * m1 * m2 * m3
        return 0.0 if den == 0 else m1 * m2 * m3 / den
    raise SystemExit("unknown t-norm " + name)


def motor(readings, tnorm, adc, terms, grid):
    """One motor's command; readings ordered (near, mid, far) for that motor."""
    sensor = SENSOR_TERMS[adc]
    aggregate = np.zeros_like(grid)
    fired = False
    for pattern, consequent in RULES:
        mu = [float(trapezoid(r, *sensor[p])) for r, p in zip(readings, pattern)]
        w = t_three(tnorm, *mu)
        if w > 0:
            fired = True
            aggregate = np.maximum(aggregate, np.minimum(w, trapezoid(grid, *terms[consequent])))
    area = np.trapz(aggregate, grid)
    if not fired or area <= 0:
        return None
    return float(np.trapz(aggregate * grid, grid) / area)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--tnorm", required=True)
    p.add_argument("--adc", type=int, default=10, choices=(10, 12))
    p.add_argument("--speed-factor", type=float, default=2.0)
    p.add_argument("--backward-slowly", default="-45,-35,-25,-15")
    p.add_argument("--points", type=int, default=400001)
    a = p.parse_args()
    k = a.speed_factor
    terms = {n: tuple(v * k for v in c) for n, c in MOTOR_TERMS.items()}
    terms["BACKWARD_SLOWLY"] = tuple(float(v) * k for v in a.backward_slowly.split(","))
    lo = min(c[0] for c in terms.values())
    hi = max(c[3] for c in terms.values())
    grid = np.linspace(lo, hi, a.points)
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["left", "mid", "right", "left_motor", "right_motor"])
    for row in csv.DictReader(sys.stdin):
        left, mid, right = (float(row[k]) for k in ("left", "mid", "right"))
        lm = motor((left, mid, right), a.tnorm, a.adc, terms, grid)
        rm = motor((right, mid, left), a.tnorm, a.adc, terms, grid)  # the mirror image
        out.writerow([row["left"], row["mid"], row["right"]] + ["" if v is None else repr(v) for v in (lm, rm)])


if __name__ == "__main__":
    main()
