#!/usr/bin/python3
"""Independent oracle for subtune against its source paper, written from the
paper's text with NumPy and SciPy and no code of this project: Georgiev,
Chetrokov & Salapateva, "Intelligent lathe turning computer control system
model" (../shared/seeds/004_1585d7a9823158a8.txt).

  level --statistic paper|slope --alpha A --min-parts N < filter output
      The filter ran over independent N(0, 1) sizes. A run's first test (the
      records with n == N) sees N fresh sizes, so the share of those that
      sub-tune is the test's real level. Checked against the level computed
      here twice: by a Monte Carlo of 200,000 samples of N sizes put through
      the printed equations,
        (4) A_Ti = a~ + i b~ (least squares), (3) S_N^2 = sum (A_i - A_Ti)^2 / (N - 1),
        (6) t = |a~ - A_TN| / S_N * sqrt(N / 2) > t_(alpha, k), k = 2 (N - 1)
      (paper; two-sided), or through Student's test of the slope at N - 2 df
      (slope), and exactly: t_slope has Student's distribution at N - 2 df
      and eq. (6)'s t is sqrt(6) N / sqrt((N + 1)(N - 2)) times it.
      Each within 4 standard errors.
  sawtooth --nominal X --wear W < trace of --simulate --policy subtune
      A lathe that wears by W per part with no noise: the sizes are exactly
      on a line, so the difference (5) is significant at the fourth piece
      ("after the fourth piece and on"), the set-up is corrected by
      dA = a~ - A_T4 = -4 W ("of value and sign corresponding to dA"), and
      "the next piece ... is considered the first in a new process": the
      sizes repeat X + W, X + 2W, X + 3W, X + 4W.
  approaches B0,B1,B2,B12,B11,B22 TARGET FEED FMIN FMAX feed.jsonl correct.jsonl
      Eq. (2), y = b0 + b1 a + b2 f + b12 a f + b11 a^2 + b22 f^2, and the
      paper's two ways of using it: with f = const, "the force-induced error
      y is determined so as to make a correction in the dimensional set-up"
      (correct: correction = -y(a, FEED)); with y = const, "determine the
      cutting feed for this particular workpiece for each depth of cut a"
      (feed: the roots of eq. (2) in f by numpy.roots; the tool takes the
      largest in [FMIN, FMAX], which the paper leaves open).
Prints one line per check; exit 1 on a failed check, 77 without SciPy.
"""
import json
import math
import sys

try:
    import numpy as np
    from scipy import stats
except ImportError:  # pragma: no cover
    print("skip: SciPy (python3-scipy) is not installed")
    sys.exit(77)

failures = 0


def report(ok, text):
    global failures
    failures += not ok
    print(("ok " if ok else "FAIL ") + text)


def option(args, name, default=None):
    return args[args.index(name) + 1] if name in args else default


def records(stream):
    return [json.loads(line) for line in stream if line.strip()]


def printed_test_alarms(sizes, alpha, statistic):
    """Rows of N sizes -> whether the test at N sub-tunes (two-sided)."""
    n = sizes.shape[1]
    i = np.arange(1, n + 1, dtype=float)
    ic = i - i.mean()
    b = (sizes - sizes.mean(axis=1, keepdims=True)) @ ic / (ic @ ic)     # b~
    a = sizes.mean(axis=1) - b * i.mean()                                # a~
    fitted = a[:, None] + b[:, None] * i                                 # (4) A_Ti
    sse = ((sizes - fitted) ** 2).sum(axis=1)
    if statistic == "paper":
        s_n = np.sqrt(sse / (n - 1))                                     # (3)
        a_tn = a + b * n
        t = np.abs(a - a_tn) / s_n * math.sqrt(n / 2)                    # (6)
        k = 2 * (n - 1)
    else:
        t = np.abs(b) / np.sqrt(sse / (n - 2) / (ic @ ic))
        k = n - 2
    return t > stats.t.isf(alpha / 2, k)


def exact_level(statistic, alpha, n):
    if statistic == "slope":
        return alpha
    ratio = math.sqrt(6) * n / math.sqrt((n + 1) * (n - 2))
    return 2 * stats.t.sf(stats.t.isf(alpha / 2, 2 * (n - 1)) / ratio, n - 2)


def level(args):
    statistic, alpha, n = option(args, "--statistic"), float(option(args, "--alpha")), int(option(args, "--min-parts"))
    first = [r for r in records(sys.stdin) if r["n"] == n]
    exact = exact_level(statistic, alpha, n)
    samples = 200000
    mc = float(printed_test_alarms(np.random.default_rng(20).standard_normal((samples, n)), alpha, statistic).mean())
    se_mc = math.sqrt(exact * (1 - exact) / samples)
    report(abs(mc - exact) <= 4 * se_mc, f"{statistic} at N = {n}, alpha {alpha}: Monte Carlo {mc:.4f}, exact {exact:.4f}")
    tool = sum(r["decision"] == "subtune" for r in first) / len(first)
    se = math.sqrt(exact * (1 - exact) / len(first))
    report(len(first) >= 1000 and abs(tool - exact) <= 4 * se,
           f"{statistic} at N = {n}, alpha {alpha}: the tool's first tests {tool:.4f} over {len(first)} runs (+- {se:.4f}), exact {exact:.4f}")


def sawtooth(args):
    nominal, wear = float(option(args, "--nominal")), float(option(args, "--wear"))
    rows = records(sys.stdin)
    for r in rows:
        phase = (r["part"] - 1) % 4 + 1
        want_size = nominal + wear * phase
        want_correction = -4 * wear if phase == 4 else 0.0
        ok = (abs(r["size"] - want_size) <= 1e-9 and r["alarm"] == (phase == 4)
              and abs(r["correction"] - want_correction) <= 1e-9)
        if not ok:
            report(False, f"part {r['part']}: {r}, want size {want_size}, correction {want_correction}")
    report(len(rows) >= 8, f"{len(rows)} parts in the cycle X + W .. X + 4W, a correction of -4W after every fourth")


def approaches(args):
    b0, b1, b2, b12, b11, b22 = map(float, args[0].split(","))
    target, feed, fmin, fmax = map(float, args[1:5])
    y = lambda a, f: b0 + b1 * a + b2 * f + b12 * a * f + b11 * a * a + b22 * f * f  # (2)
    fed, corrected = records(open(args[5])), records(open(args[6]))
    for r in corrected:
        want = -y(r["a"], feed)
        report(abs(r["correction"] - want) <= 1e-12, f"f = const: a {r['a']}, correction {r['correction']:.6g}, -y {want:.6g}")
    for r in fed:
        a = r["a"]
        roots = np.roots([b22, b2 + b12 * a, b0 + b1 * a + b11 * a * a - target] if b22 else [b2 + b12 * a, b0 + b1 * a + b11 * a * a - target])
        inside = [x.real for x in roots if abs(x.imag) <= 1e-12 and fmin - 1e-12 <= x.real <= fmax + 1e-12]
        if inside:
            ok = r["feed_status"] == "solved" and abs(r["feed"] - max(inside)) <= 1e-9 and abs(r["predicted_error"] - target) <= 1e-12
        else:
            ok = r["feed_status"] == "none" and r["feed"] is None
        report(ok, f"y = const: a {a}, feed {r['feed']}, roots in range {sorted(inside)}")


def main():
    if len(sys.argv) < 2 or sys.argv[1] not in ("level", "sawtooth", "approaches"):
        print(__doc__)
        return 2
    {"level": level, "sawtooth": sawtooth, "approaches": approaches}[sys.argv[1]](sys.argv[2:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
