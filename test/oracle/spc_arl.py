#!/usr/bin/python3
"""Independent oracle for subtune --simulate: average run lengths (ARL) of
the Shewhart, EWMA and tabular CUSUM charts for N(delta, 1) observations,
computed here from the charts' definitions and no code of this project.

  Shewhart X of individuals, limits +-L: exact, p = Phi(-L - d) + 1 - Phi(L - d),
      ARL = 1 / p for a step d; under a drift (mean d_i = s + r i at part
      i = 1, 2, ...) ARL = sum_n prod_{i <= n} (1 - p_i).
  EWMA z_i = lam x_i + (1 - lam) z_{i-1}, z_0 = 0, asymptotic limits
      +-L sqrt(lam / (2 - lam)): Markov chain of Brook & Evans (1972) with m
      states of equal width over the in-control band (Lucas & Saccucci 1990).
  Tabular CUSUM C+ = max(0, C+ + x - k), C- = max(0, C- - x - k), alarm when
      either exceeds h: Brook & Evans' chain for each one-sided CUSUM (state
      0 holds the atom at zero, width w = 2h / (2m - 1)), combined by
      1/ARL = 1/ARL+ + 1/ARL- (Lucas & Crosier 1982; what SAS's CUSUMARL and
      Montgomery's table use); 'selfcheck' also solves the 2-D chain on
      (C+, C-), which agrees with the combination to rounding (for the
      zero-start two-sided scheme the relation holds exactly).
  Under a drift the chains are propagated part by part with the part's own
  transition matrix (zero state at the first part), and for the CUSUM the
  two one-sided survival functions are multiplied (independence; the lower
  side practically never signals under an upward drift).

Each ARL comes with a discretisation error estimate |ARL(m) - ARL(m/2)|.

Usage:
  spc_arl.py selfcheck
      reproduces published values (Shewhart 3 sigma: 370.4 and 43.9 at 1
      sigma; CUSUM k 0.5, h 5: 465 and 10.4 (Montgomery); SAS/QC's
      EWMAARL(1, 0.25, 3) = 11.154267016) and prints the EWMA lam 0.2, L 3
      figures; exit 1 when one is off.
  spc_arl.py table [--shift D] [--drift R] [chart options]
      one JSON object: {chart: {arl0, arl_shift, arl_drift, *_err}}.
  spc_arl.py compare [--sigmas 4] [--published] [chart options] < summaries
      reads subtune --simulate summary records (JSON Lines) and checks each
      shewhart/ewma/cusum record's arl0, arl_shift and arl_drift against the
      chain within SIGMAS of the record's own *_se (plus the chain's error);
      with --published also arl0/arl_shift against the published figures
      (only for the default charts, shift 1). Prints one line per check.
Chart options: --shewhart-l 3 --ewma-lambda 0.2 --ewma-l 3 --cusum-k 0.5
  --cusum-h 5 --shift 1 --drift 0.1 --states 400
Exit status 0 on success, 1 on a failed check, 77 when SciPy is missing.
"""
import argparse
import json
import math
import sys

try:
    import numpy as np
    from scipy.stats import norm
    import scipy.sparse
    import scipy.sparse.linalg
except ImportError:  # pragma: no cover
    print("skip: SciPy (python3-scipy) is not installed")
    sys.exit(77)


# --------------------------------------------------------------- Shewhart
def shewhart_p(L, d):
    return norm.cdf(-L - d) + norm.sf(L - d)


def shewhart_arl(L, d):
    return 1.0 / shewhart_p(L, d)


def survival_sum(step_probability, tol=1e-13, cap=10**7):
    """sum_{n >= 0} prod_{i=1..n} (1 - p_i) for a part-indexed alarm probability."""
    total, survive, i = 1.0, 1.0, 0
    while survive > tol and i < cap:
        i += 1
        survive *= 1.0 - step_probability(i)
        total += survive
    return total


def shewhart_drift_arl(L, shift, drift):
    return survival_sum(lambda i: shewhart_p(L, shift + drift * i))


# ------------------------------------------------------ Markov chains
class MarkovChain:
    """A chart's statistic on m discrete states (Brook & Evans): subclasses
    give matrix(mean), the transition probabilities among the in-control
    states for one part with that mean, and start, the zero state."""

    def arl(self, mean):
        P = self.matrix(mean)
        return np.linalg.solve(np.eye(self.m) - P, np.ones(self.m))[self.start]

    def survival(self, mean_at, tol=1e-13, cap=10**6):
        """The zero-state survival function S(n), n = 0, 1, ... under a part-indexed mean."""
        p = np.zeros(self.m)
        p[self.start] = 1.0
        out, i = [1.0], 0
        while out[-1] > tol and i < cap:
            i += 1
            p = p @ self.matrix(mean_at(i))
            out.append(float(p.sum()))
        return np.array(out)


# ------------------------------------------------------------------- EWMA
class EwmaChain(MarkovChain):
    def __init__(self, lam, L, m):
        if m % 2 == 0:
            m += 1  # an odd count puts z0 = 0 at a state's centre
        self.lam, self.m = lam, m
        self.h = L * math.sqrt(lam / (2.0 - lam))
        self.w = 2.0 * self.h / m
        self.c = -self.h + self.w * (np.arange(m) + 0.5)
        self.start = m // 2

    def matrix(self, mean):
        lam, c, w = self.lam, self.c, self.w
        base = (1.0 - lam) * c[:, None]
        upper = (c[None, :] + w / 2 - base) / lam - mean
        lower = (c[None, :] - w / 2 - base) / lam - mean
        return norm.cdf(upper) - norm.cdf(lower)


# ------------------------------------------------------------------ CUSUM
class CusumChain(MarkovChain):
    """The upper one-sided CUSUM C = max(0, C + x - k), alarm C > h."""

    def __init__(self, k, h, m):
        self.k, self.h, self.m = k, h, m
        self.w = 2.0 * h / (2 * m - 1)
        self.c = self.w * np.arange(m)
        self.edges = (np.arange(m) + 0.5) * self.w  # upper edges; the last is h
        self.start = 0

    def matrix(self, mean):
        cdf = norm.cdf(self.edges[None, :] - self.c[:, None] + self.k - mean)
        return np.diff(np.concatenate([np.zeros((self.m, 1)), cdf], axis=1), axis=1)

    def two_sided_arl(self, d):
        # the lower CUSUM at mean d is the upper one at -d
        return 1.0 / (1.0 / self.arl(d) + 1.0 / self.arl(-d))

    def two_sided_drift_arl(self, shift, drift):
        up = self.survival(lambda i: shift + drift * i)
        down = self.survival(lambda i: -(shift + drift * i), tol=0.0, cap=len(up) - 1)
        return float(np.sum(up * down[: len(up)]))


def cusum_2d_arl(k, h, d, m):
    """Exact two-sided tabular CUSUM as one chain on (C+, C-), m states per side."""
    w = 2.0 * h / (2 * m - 1)
    c = w * np.arange(m)
    ci, cj = np.meshgrid(c, c, indexing="ij")
    ci, cj = ci.ravel(), cj.ravel()
    half = (np.arange(m) + 0.5) * w
    u = half[None, :] + k - ci[:, None]      # x >= u[a]: C+' past bin a
    v = cj[:, None] - k - half[None, :]      # x <= v[b]: C-' past bin b
    cuts = np.sort(np.concatenate([u, v], axis=1), axis=1)
    lo = np.concatenate([np.full((cuts.shape[0], 1), -np.inf), cuts], axis=1)
    hi = np.concatenate([cuts, np.full((cuts.shape[0], 1), np.inf)], axis=1)
    mid = np.where(np.isinf(lo), hi - 1.0, np.where(np.isinf(hi), lo + 1.0, 0.5 * (lo + hi)))
    a = np.clip(np.floor((mid + ci[:, None] - k) / w + 0.5), 0, m).astype(int)
    b = np.clip(np.floor((cj[:, None] - k - mid) / w + 0.5), 0, m).astype(int)
    prob = norm.cdf(hi - d) - norm.cdf(lo - d)
    rows = np.broadcast_to(np.arange(m * m)[:, None], a.shape)
    keep = (a < m) & (b < m) & (prob > 0)
    P = scipy.sparse.csr_matrix((prob[keep], (rows[keep], (a * m + b)[keep])), shape=(m * m, m * m))
    A = scipy.sparse.identity(m * m, format="csc") - P.tocsc()
    return float(scipy.sparse.linalg.spsolve(A, np.ones(m * m))[0])


# ------------------------------------------------------------------ figures
def with_error(f, m):
    """f(m) and |f(m) - f(m/2)| as the discretisation error estimate."""
    fine, coarse = f(m), f(max(m // 2, 10))
    return float(fine), float(abs(fine - coarse))


def figures(o):
    s, r = o.shift, o.drift
    out = {}
    L = o.shewhart_l
    out["shewhart"] = {
        "arl0": shewhart_arl(L, 0.0), "arl0_err": 0.0,
        "arl_shift": shewhart_arl(L, s), "arl_shift_err": 0.0,
        "arl_drift": shewhart_drift_arl(L, 0.0, r), "arl_drift_err": 0.0,
    }
    e = {}
    e["arl0"], e["arl0_err"] = with_error(lambda m: EwmaChain(o.ewma_lambda, o.ewma_l, m).arl(0.0), o.states)
    e["arl_shift"], e["arl_shift_err"] = with_error(lambda m: EwmaChain(o.ewma_lambda, o.ewma_l, m).arl(s), o.states)
    e["arl_drift"], e["arl_drift_err"] = with_error(
        lambda m: EwmaChain(o.ewma_lambda, o.ewma_l, m).survival(lambda i: r * i).sum(), o.states)
    out["ewma"] = e
    c = {}
    c["arl0"], c["arl0_err"] = with_error(lambda m: CusumChain(o.cusum_k, o.cusum_h, m).two_sided_arl(0.0), o.states)
    c["arl_shift"], c["arl_shift_err"] = with_error(lambda m: CusumChain(o.cusum_k, o.cusum_h, m).two_sided_arl(s), o.states)
    c["arl_drift"], c["arl_drift_err"] = with_error(
        lambda m: CusumChain(o.cusum_k, o.cusum_h, m).two_sided_drift_arl(0.0, r), o.states)
    out["cusum"] = c
    return out


# Published figures for the default charts (3 sigma Shewhart, CUSUM k 0.5
# h 5) as (value, half-width of its last printed digit + rounding slack).
PUBLISHED = {
    ("shewhart", "arl0"): (370.4, 0.05),    # 1 / 0.0027
    ("shewhart", "arl_shift"): (43.9, 0.05),
    ("cusum", "arl0"): (465.0, 0.5),        # Montgomery, Introduction to SQC, two-sided tabular CUSUM
    ("cusum", "arl_shift"): (10.4, 0.05),
}


def selfcheck(o):
    bad = 0

    def check(label, got, want, tol):
        nonlocal bad
        ok = abs(got - want) <= tol
        bad += not ok
        print(f"{'ok' if ok else 'FAIL'}: {label}: {got:.6g} (published {want}, tolerance {tol:g})")

    check("Shewhart L 3 in control", shewhart_arl(3, 0), 370.4, 0.05)
    check("Shewhart L 3 at 1 sigma", shewhart_arl(3, 1), 43.9, 0.05)
    cus = CusumChain(0.5, 5, o.states)
    check("CUSUM k 0.5 h 5 in control (two-sided)", cus.two_sided_arl(0), 465, 0.5)
    check("CUSUM k 0.5 h 5 at 1 sigma (two-sided)", cus.two_sided_arl(1), 10.4, 0.05)
    check("CUSUM k 0.5 h 5 one-sided in control (Siegmund ~ 930)", cus.arl(0), 930.0, 2.0)
    # SAS/QC documentation, EWMAARL function: EWMAARL(1.00, 0.25, 3.0) returns 11.154267016.
    check("EWMA lam 0.25 L 3 at 1 sigma (SAS EWMAARL)", EwmaChain(0.25, 3, 2 * o.states).arl(1.0), 11.154267016, 2e-4)
    # The 2-D chain on (C+, C-) against the combination 1/ARL = 1/ARL+ + 1/ARL-.
    m2 = 60
    for d in (0.0, 1.0):
        exact = cusum_2d_arl(0.5, 5, d, m2)
        combined = CusumChain(0.5, 5, m2).two_sided_arl(d)
        rel = abs(exact - combined) / exact
        ok = rel < 1e-6
        bad += not ok
        print(f"{'ok' if ok else 'FAIL'}: CUSUM 2-D chain ({m2}x{m2} states) at {d:g} sigma: {exact:.6g}, "
              f"combined one-sided chains {combined:.6g}, relative difference {rel:.2g}")
    for d in (0.0, 1.0):
        arl, err = with_error(lambda m: EwmaChain(0.2, 3, m).arl(d), o.states)
        fine = EwmaChain(0.2, 3, 4 * o.states).arl(d)
        print(f"info: EWMA lam 0.2 L 3 at {d:g} sigma: {arl:.6g} ({o.states} states; "
              f"{4 * o.states} states: {fine:.7g}; change from {o.states // 2} states {err:.2g})")
    return bad


def compare(o):
    want = figures(o)
    bad = checked = 0
    for line in sys.stdin:
        if not line.strip():
            continue
        rec = json.loads(line)
        chart = rec.get("policy")
        if chart not in want:
            continue
        for field in ("arl0", "arl_shift", "arl_drift"):
            got, se = rec.get(field), rec.get(field + "_se")
            ref, err = want[chart][field], want[chart][field + "_err"]
            if got is None or se is None:
                print(f"FAIL: {chart} {field}: missing in the record")
                bad += 1
                continue
            tol = o.sigmas * se + err
            ok = abs(got - ref) <= tol
            checked += 1
            bad += not ok
            print(f"{'ok' if ok else 'FAIL'}: {chart} {field}: tool {got:.6g} +- {se:.3g}, chain {ref:.6g} "
                  f"(|diff| {abs(got - ref):.3g} <= {tol:.3g}, {abs(got - ref) / se:.2f} se)")
            key = (chart, field)
            if o.published and key in PUBLISHED:
                value, slack = PUBLISHED[key]
                tol = o.sigmas * se + slack
                ok = abs(got - value) <= tol
                checked += 1
                bad += not ok
                print(f"{'ok' if ok else 'FAIL'}: {chart} {field}: tool {got:.6g} against published {value} "
                      f"(|diff| {abs(got - value):.3g} <= {tol:.3g})")
    if checked == 0:
        print("FAIL: no shewhart/ewma/cusum summary records on stdin")
        return 1
    return bad


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mode", choices=["selfcheck", "table", "compare"])
    p.add_argument("--shewhart-l", type=float, default=3.0)
    p.add_argument("--ewma-lambda", type=float, default=0.2)
    p.add_argument("--ewma-l", type=float, default=3.0)
    p.add_argument("--cusum-k", type=float, default=0.5)
    p.add_argument("--cusum-h", type=float, default=5.0)
    p.add_argument("--shift", type=float, default=1.0)
    p.add_argument("--drift", type=float, default=0.1)
    p.add_argument("--states", type=int, default=400)
    p.add_argument("--sigmas", type=float, default=4.0)
    p.add_argument("--published", action="store_true")
    o = p.parse_args()
    if o.mode == "selfcheck":
        return 1 if selfcheck(o) else 0
    if o.mode == "table":
        print(json.dumps(figures(o)))
        return 0
    return 1 if compare(o) else 0


if __name__ == "__main__":
    sys.exit(main())
