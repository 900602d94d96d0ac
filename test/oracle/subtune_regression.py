#!/usr/bin/python3
"""Independent oracle for subtune's filter: recomputes every part's figures
from the sizes alone, with scipy.stats.linregress, numpy and
scipy.stats.t (its sf inverted by brentq), and no code of this project.

Written from the paper's text (Georgiev, Chetrokov & Salapateva,
"Intelligent lathe turning computer control system model", section 3.3.2,
../shared/seeds/004_1585d7a9823158a8.txt): "after the fourth piece and on,
the regression equation is determined"; the pieces of the current process
are i = 1..N with sizes A_i, and
  (4) A_Ti = a~ + i b~                       (the least-squares line)
  (3) S_N^2 = sum (A_i - A_Ti)^2 / (N - 1)
  (5) dA = a~ - A_TN
  (6) t = |a~ - A_TN| / S_N * sqrt(N / 2) > t_(alpha, k),  k = 2 (N - 1)
"The moment the difference (5) becomes significant, dimensional sub tuning
of value and sign corresponding to dA is performed. The next piece, after
the extra set-up, is considered the first in a new process."
--statistic paper computes (3)-(6) literally, from a~ and A_TN. The
default, --statistic slope, tests the same difference (5) with the standard
error that the regression gives it: t = |b~| / stderr(b~), stderr as
linregress reports it (s^2 = SSE / (N - 2)), at N - 2 df.
  --resolution r:  S = max(S, r / sqrt(12)); S = 0 gives t = 0 when b = 0 and
                   t = inf (written null) otherwise
  two-sided:       t_crit = the t with t.sf(t, df) = alpha / 2, significant when t > t_crit
  greater / less:  t_crit = the t with t.sf(t, df) = alpha, and b > 0 / b < 0 as well
No test while N < --min-parts (decision insufficient; a, b null at N = 1;
s, t, t_crit, df null). On a significant difference: decision subtune,
correction = dA = a~ - A_TN (or X - A_TN with --correct-to nominal
--nominal X), offset = the sum of the corrections so far, and the next part
opens a new run (run + 1, n = 1). Otherwise decision none, correction 0.
With --lower/--upper or a record's lower/upper fields, in_tolerance says
whether the size lies in [lower, upper].

Usage: subtune_regression.py [subtune's options] < subtune-output.jsonl
       subtune_regression.py --cases FILE
  --cases: each line of FILE is "OUTPUT.jsonl [subtune's options]"; every
  output is checked in this one process (SciPy starts once), one summary
  line per case, exit 1 if any case fails.
  options: --field size --alpha 0.05 --statistic slope|paper
           --alternative two-sided|greater|less --min-parts 4
           --resolution 0 --correct-to start|nominal --nominal X
           --lower L --upper U --rtol 1e-8
The fit runs on the sizes divided by a power of two near their magnitude,
so sizes whose squares leave the double range are still fitted exactly.
A decision within 1e-9 (relative) of the threshold is accepted either way,
and after a wrong decision (reported) the oracle follows the tool's choice
to stay in step.
Prints one line per mismatch and a summary; exit 1 on any mismatch (or no
records), 77 when SciPy is missing.
"""
import argparse
import functools
import json
import math
import sys
import warnings

try:
    import numpy as np
    from scipy import optimize, stats
except ImportError:  # pragma: no cover
    print("skip: SciPy (python3-scipy) is not installed")
    sys.exit(77)

warnings.simplefilter("ignore")  # linregress on 2 points or constant sizes warns about its own stderr

@functools.lru_cache(maxsize=None)
def t_quantile(upper_tail, df):
    """t with P(T > t) = upper_tail at df degrees of freedom: t.sf inverted by
    brentq. (SciPy 1.10's t.ppf, Cephes' stdtrit, is off by ~1e-9 relative,
    e.g. 2.44691184879 for 2.44691185114 at df 6; t.sf itself, through the
    incomplete beta function, is accurate to rounding.)"""
    guess = float(stats.t.isf(upper_tail, df))
    lo, hi = guess * (1 - 1e-6), guess * (1 + 1e-6)
    return optimize.brentq(lambda x: stats.t.sf(x, df) - upper_tail, lo, hi, xtol=1e-15, rtol=1e-15)


HUGE = 1e8  # a t above this counts as the 'infinite' t of a (numerically) perfect line


def parse(args=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--field", default="size")
    p.add_argument("--alpha", type=float, default=0.05)
    p.add_argument("--statistic", choices=["slope", "paper"], default="slope")
    p.add_argument("--alternative", choices=["two-sided", "greater", "less"], default="two-sided")
    p.add_argument("--min-parts", type=int, default=4)
    p.add_argument("--resolution", type=float, default=0.0)
    p.add_argument("--correct-to", choices=["start", "nominal"], default="start")
    p.add_argument("--nominal", type=float)
    p.add_argument("--lower", type=float)
    p.add_argument("--upper", type=float)
    p.add_argument("--rtol", type=float, default=1e-8)
    return p.parse_args(args)


class Checker:
    def __init__(self, rtol):
        self.rtol = rtol
        self.errors = 0

    def fail(self, line, field, got, want):
        self.errors += 1
        if self.errors <= 50:
            print(f"line {line}: {field}: tool {got!r}, oracle {want!r}")

    def null(self, line, rec, field):
        if rec.get(field, "absent") is not None:
            self.fail(line, field, rec.get(field, "absent"), None)

    def exact(self, line, rec, field, want):
        if rec.get(field) != want:
            self.fail(line, field, rec.get(field), want)

    def close(self, line, rec, field, want, tol):
        """|tool - want| <= tol."""
        got = rec.get(field)
        if not isinstance(got, (int, float)) or isinstance(got, bool) or abs(got - want) > tol:
            self.fail(line, field, got, want)


def check(o, stream):
    """Checks subtune's output on STREAM against options O; returns the exit status."""
    if o.correct_to == "nominal" and o.nominal is None:
        print("subtune_regression.py: --correct-to nominal needs --nominal")
        return 2
    ck = Checker(o.rtol)
    run, sizes, offset = 1, [], 0.0
    records = subtunes = 0
    for line_no, line in enumerate(stream, 1):
        if not line.strip():
            continue
        rec = json.loads(line)
        records += 1
        y = float(rec[o.field])
        sizes.append(y)
        n = len(sizes)
        ck.exact(line_no, rec, "run", run)
        ck.exact(line_no, rec, "n", n)
        scale = max(abs(v) for v in sizes) + 1e-300  # rounding of the sums grows with the sizes' magnitude
        # The fit runs on the sizes divided by a power of two near their
        # magnitude (exact), so that squares of sizes near 1e300 (or 1e-300)
        # neither overflow nor underflow; a, b, S scale back by the same power.
        e = math.frexp(scale)[1]
        i = np.arange(1, n + 1, dtype=float)
        ys = np.ldexp(np.array(sizes), -e)
        a = b = a_u = b_u = None
        if n == 1:
            ck.null(line_no, rec, "a")
            ck.null(line_no, rec, "b")
        else:
            fit = stats.linregress(i, ys)
            a_u, b_u = float(fit.intercept), float(fit.slope)
            a, b = math.ldexp(a_u, e), math.ldexp(b_u, e)
            ck.close(line_no, rec, "a", a, o.rtol * scale)
            ck.close(line_no, rec, "b", b, o.rtol * scale)
        decision, correction = "none", 0.0
        if n < o.min_parts:
            decision = "insufficient"
            for field in ("s", "t", "t_crit", "df"):
                ck.null(line_no, rec, field)
        else:
            a_t = a_u + b_u * i                      # (4) A_Ti, scaled
            a_tn = a_u + b_u * n                     # A_TN
            floor = math.ldexp(o.resolution / math.sqrt(12.0), -e)
            if o.statistic == "paper":
                df = 2 * (n - 1)                                            # k in (6)
                s_u = math.sqrt(float(np.sum((ys - a_t) ** 2)) / (n - 1))  # (3)
                s_u = max(s_u, floor)
                scale_t = math.sqrt(n / 2.0)                                # (6)
            else:
                df = n - 2
                # linregress's stderr of the slope is s / sqrt(Sxx), s^2 = SSE / (N - 2):
                # the standard error of dA = -N b~ is N s / sqrt(Sxx)
                sxx = float(np.sum((i - i.mean()) ** 2))
                s_u = max(float(fit.stderr) * math.sqrt(sxx), floor)
                scale_t = math.sqrt(sxx) / n
            s = math.ldexp(s_u, e)
            degenerate = s_u <= 1e-12  # a (numerically) perfect line: S is rounding noise
            rise = abs(a_u - a_tn)                   # |dA| of (5), scaled
            if s_u > 0:
                t = rise / s_u * scale_t
            else:
                t = math.inf if b_u != 0 else 0.0
            tail = o.alpha / 2 if o.alternative == "two-sided" else o.alpha
            t_crit = t_quantile(tail, df)
            ck.exact(line_no, rec, "df", df)
            ck.close(line_no, rec, "t_crit", t_crit, 1e-10 * t_crit)
            # Rounding in the tool's sums is of order eps * (the sizes' magnitude):
            # absolute terms in units of the sizes (S) and of S (t) cover it.
            if not degenerate:
                ck.close(line_no, rec, "s", s, o.rtol * s + 1e-12 * scale)
            elif not (isinstance(rec.get("s"), (int, float)) and abs(rec["s"]) <= 1e-9 * scale + s):
                ck.fail(line_no, "s", rec.get("s"), s)
            got_t = rec.get("t")
            if degenerate and (t == math.inf or t > HUGE):
                if not (got_t is None or got_t > HUGE):
                    ck.fail(line_no, "t", got_t, t)
            elif degenerate and t == 0.0:
                if not (isinstance(got_t, (int, float)) and got_t == 0.0):
                    ck.fail(line_no, "t", got_t, t)
            else:
                ck.close(line_no, rec, "t", t, o.rtol * t + 1e-12 * n ** 1.5 / s_u)
            direction_ok = {"two-sided": True, "greater": b_u > 0, "less": b_u < 0}[o.alternative]
            significant = t > t_crit and direction_ok
            near_tie = direction_ok and abs(t - t_crit) <= 1e-9 * t_crit
            if near_tie:
                significant = rec.get("decision") == "subtune"
            if significant:
                decision = "subtune"
                level = a + b * n                    # A_TN
                correction = (a - level) if o.correct_to == "start" else (o.nominal - level)  # (5): dA = a~ - A_TN
        if rec.get("decision") != decision:
            ck.fail(line_no, "decision", rec.get("decision"), decision)
            # stay in step with the tool: its decision decides the runs from here
            if rec.get("decision") in ("none", "subtune", "insufficient"):
                decision = rec["decision"]
                correction = rec.get("correction") or 0.0
        elif decision == "subtune":
            ck.close(line_no, rec, "correction", correction, o.rtol * scale)
        else:
            ck.exact(line_no, rec, "correction", 0.0)
        offset += correction
        ck.close(line_no, rec, "offset", offset, o.rtol * scale * max(1, subtunes + 1))
        # a record's limits override the options; an empty CSV cell is no limit
        lower = rec.get("lower") if rec.get("lower") not in (None, "") else o.lower
        upper = rec.get("upper") if rec.get("upper") not in (None, "") else o.upper
        if lower is not None or upper is not None:
            inside = (lower is None or y >= float(lower)) and (upper is None or y <= float(upper))
            ck.exact(line_no, rec, "in_tolerance", inside)
        elif "in_tolerance" in rec:
            ck.fail(line_no, "in_tolerance", rec["in_tolerance"], "absent")
        if decision == "subtune":
            subtunes += 1
            run += 1
            sizes = []
    print(f"{records} records, {run} runs, {subtunes} subtunes, {ck.errors} mismatches")
    if records == 0:
        print("no records on stdin")
        return 1
    return 1 if ck.errors else 0


def main():
    if sys.argv[1:2] == ["--cases"] and len(sys.argv) == 3:
        worst = 0
        with open(sys.argv[2]) as cases:
            for case in cases:
                words = case.split()
                if not words:
                    continue
                print(" ".join(words) + ":", end=" ")
                with open(words[0]) as output:
                    worst = max(worst, check(parse(words[1:]), output))
        return worst
    return check(parse(), sys.stdin)


if __name__ == "__main__":
    sys.exit(main())
