#!/usr/bin/python3
"""Independent oracle for smcsim: the sampled PID loop on the feed drive
m x'' + b x' = F - F_d(t), simulated with SciPy's solve_ivp (DOP853) and the
continuous milling force, written here from the model's formulas and not
from any code of this project.

The loop (smcsim's smooth case: --encoder 0 --position-filter 0
--velocity-filter 0, so the controller sees the true position):
  at t_k = k T the controller reads x_k = x(t_k) and the velocity estimate
  (x_k - x_{k-1}) / T (at k = 0 the true initial velocity), and computes
    F_k = m^ a_ref + b^ v_ref + k_p e_k + k_i I_k + k_d (v_ref - v^_k),
    e_k = x_ref(t_k) - x_k,  I_k = T (e_0 + ... + e_{k-1}),
  clipped at K_t K_a V; F_k is held over [t_k, t_k + T) while the plant
  integrates with the cutting force F_d(t) evaluated continuously:
    F_d = sum over teeth in the cut (0 <= phi <= phi_exit) of
          F_t cos phi + F_r sin phi,  F_t = a K_tc f_z sin phi,
          F_r = a K_rc f_z sin phi,   phi_j = Omega t + 2 pi j / N.
  The integration restarts at every sample and at every tooth entry and
  exit (where F_d has a kink), so DOP853 never steps over a corner.

The sliding-mode loops (mode 'law') replace the PID by the paper's laws
(Rubio, Ibeas & Kollar, eq. 3, 6, 8, 9), with the same samples:
    S_k = (v_ref - v^_k) + mu e_k + lambda I_k                       (eq. 3)
  the equivalent part either as eq. 6 solved for F with the estimates,
    surface: m^ (a_ref + mu (v_ref - v^_k) + lambda e_k) + b^ v^_k,
  or the bracket printed in eq. 8 and 9 (b/m read as b^/m^),
    printed: m^ (a_ref + (b^/m^) v_ref + lambda e_k),
  and the switching part with sigma = +1 (the sign that stabilises) or
  sigma = -1 (the printed -Lambda sign(S)):
    smc: F_k = equivalent + sigma Lambda sign(S_k)                     (eq. 8)
    sta: F_k = equivalent + sigma (alpha |S_k|^1/2 sign(S_k) + w_k),
         w_{k+1} = w_k + T beta sign(S_k)                            (eq. 9)
  The gains are given in smcsim's --units (length unit u = 1e-3 m for mm,
  1 m for m; forces in kg u/s^2) and turned into SI here: Lambda u newtons,
  alpha sqrt(u) N/(m/s)^1/2 (S is in u/s under the root), beta u N/s.

Everything is in SI units (m, N); smcsim writes mm and N.

Usage (smcsim on PATH, or --smcsim PATH):
  feed_drive_ivp.py compare  [--period T] [--substeps N] [--no-cut] [--feed F] [--tol R]
                             [--ftol RF] [--effect-share S]
      max |x_tool - x_oracle| / max |x_oracle| must be <= R (default 1e-6)
      and <= S (default 1e-3) times the cut's own effect on x, the same for
      F must be <= RF (default 1e-4)
  feed_drive_ivp.py converge [--period T] [--substeps 1,2,4,8] [--feed F]
                             [--min-order 1.8] [--max-order 2.3]
      the error against the oracle at each substep count, and the observed
      order log2(err(n) / err(2n)) of each halving, which must lie in range
  feed_drive_ivp.py exact    [--period T] [--substeps 1,2,4,8] [--tol 1e-10]
      without the cut the held-force step is exact: every substep count
      must match the oracle to within R
  feed_drive_ivp.py law      --controller smc|sta [--bracket surface|printed] [--seed-sign]
                             [--Lambda L] [--alpha A] [--beta B] [--units mm|m] [--duration D]
                             [--period T] [--substeps N] [--no-cut] [--tol R] [--ftol RF]
      the sliding-mode loop: x and F within R (default 1e-6) and RF
      (default 1e-4) of the oracle, relative to their largest values
Exit status 0 on success, 1 on a failed check, 77 when SciPy is missing.
"""
import argparse
import csv
import io
import math
import subprocess
import sys

try:
    import numpy as np
    from scipy.integrate import solve_ivp
except ImportError:  # pragma: no cover
    print("skip: SciPy (python3-scipy) is not installed")
    sys.exit(77)

# The run, passed to smcsim explicitly (the oracle does not lean on its defaults).
MASS, DAMPING = 10.0, 250.0           # kg, kg/s
MASS_HAT, DAMPING_HAT = 7.0, 200.0    # the controller's model
KP, KI, KD = 330000.0, 1.4e7, 2400.0  # kg/s^2, kg/s^3, kg/s: about a triple pole at 20 Hz
AMPLITUDE, OMEGA = 1e-3, 3.0          # reference 1 mm sin(3 t), in metres
FORCE_LIMIT = 2.0 * 50.0 * 10.0       # K_t K_a V, N
TEETH, DIAMETER, SPINDLE, AXIAL = 2, 0.9, 11520.0, 0.9  # -, mm, rpm, mm (a full slot)
KTC, KRC = 767.01, 168.8              # N/mm^2
MU, LAMBDA = 2.0, 1.0                 # the surface's (mu, lambda), 1/s and 1/s^2


def law_args(opts):
    """smcsim's options for the loop's controller: the PID, or the law of mode 'law'."""
    if opts.mode != "law":
        return ["--controller", "pid", "--kp", repr(KP), "--ki", repr(KI), "--kd", repr(KD), "--pid-ff", "1"]
    args = ["--controller", opts.controller, "--mu", repr(MU), "--lambda", repr(LAMBDA), "--units", opts.units,
            "--Lambda", repr(opts.Lambda), "--alpha", repr(opts.alpha), "--beta", repr(opts.beta)]
    return args + (["--seed-bracket"] if opts.bracket == "printed" else []) + (["--seed-sign"] if opts.seed_sign else [])


def smcsim_args(opts, substeps, cut):
    args = [opts.smcsim] + law_args(opts) + [
            "--mass", repr(MASS), "--damping", repr(DAMPING),
            "--mass-estimate", repr(MASS_HAT), "--damping-estimate", repr(DAMPING_HAT),
            "--kt", "2", "--ka", "50", "--voltage-limit", "10",
            "--reference", "sine", "--amplitude", "1", "--omega", repr(OMEGA),
            "--teeth", str(TEETH), "--tool-diameter", repr(DIAMETER), "--spindle", repr(SPINDLE),
            "--axial-depth", repr(AXIAL), "--feed", repr(opts.feed), "--ktc", repr(KTC), "--krc", repr(KRC),
            "--kte", "0", "--kre", "0",
            "--encoder", "0", "--position-filter", "0", "--velocity-filter", "0",
            "--duration", repr(opts.duration), "--period", repr(opts.period), "--substeps", str(substeps),
            "--every", "1", "--csv"]
    if not cut:
        args.append("--no-cut")
    return args


def run_smcsim(opts, substeps, cut):
    """t (s), x (m), F (N) columns of smcsim's time series."""
    out = subprocess.run(smcsim_args(opts, substeps, cut), check=True, capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    t = np.array([float(r["t"]) for r in rows])
    x = np.array([float(r["x"]) for r in rows]) * 1e-3
    f = np.array([float(r["F"]) for r in rows])
    return t, x, f


class Cut:
    """The feed-direction force of a full-slot cut, shear terms only, in N."""

    def __init__(self, feed_mm_min, enabled):
        self.enabled = enabled and feed_mm_min > 0
        self.omega = SPINDLE / 60.0 * 2 * math.pi
        fz = feed_mm_min / (SPINDLE * TEETH)  # mm per tooth
        self.kt, self.kr = AXIAL * KTC * fz, AXIAL * KRC * fz  # N per unit sin(phi)
        self.exit = math.pi  # a slot: the tooth cuts from 0 to pi

    def force(self, t):
        if not self.enabled:
            return 0.0
        total = 0.0
        for j in range(TEETH):
            phi = math.fmod(self.omega * t + 2 * math.pi * j / TEETH, 2 * math.pi)
            if 0 <= phi <= self.exit:
                s, c = math.sin(phi), math.cos(phi)
                total += self.kt * s * c + self.kr * s * s
        return total

    def corners(self, t0, t1):
        """Times in (t0, t1) where a tooth enters (phi = 0) or leaves (phi = exit)."""
        if not self.enabled:
            return []
        out = []
        for j in range(TEETH):
            for edge in (0.0, self.exit):
                # omega t + 2 pi j / N = edge + 2 pi m
                base = edge - 2 * math.pi * j / TEETH
                m = math.ceil((self.omega * t0 - base) / (2 * math.pi))
                while True:
                    t = (base + 2 * math.pi * m) / self.omega
                    if t >= t1:
                        break
                    if t > t0:
                        out.append(t)
                    m += 1
        return sorted(out)


def pid_law(period):
    def force(a_ref, v_ref, e, e_rate, integral, v_hat):
        return MASS_HAT * a_ref + DAMPING_HAT * v_ref + KP * e + KI * integral + KD * e_rate
    return force


def sliding_law(opts, period):
    """Eq. 8 or 9 with the chosen bracket and sign, in SI units."""
    u = 1e-3 if opts.units == "mm" else 1.0
    big_lambda, alpha, beta = opts.Lambda * u, opts.alpha * math.sqrt(u), opts.beta * u
    sigma = -1.0 if opts.seed_sign else 1.0
    w = [0.0]  # the super-twisting integral, N

    def force(a_ref, v_ref, e, e_rate, integral, v_hat):
        s = e_rate + MU * e + LAMBDA * integral
        sign = (s > 0) - (s < 0)
        if opts.bracket == "printed":
            equivalent = MASS_HAT * (a_ref + DAMPING_HAT / MASS_HAT * v_ref + LAMBDA * e)
        else:
            equivalent = MASS_HAT * (a_ref + MU * e_rate + LAMBDA * e) + DAMPING_HAT * v_hat
        if opts.controller == "smc":
            return equivalent + sigma * big_lambda * sign
        f = equivalent + sigma * (alpha * math.sqrt(abs(s)) * sign + w[0])
        w[0] += period * beta * sign
        return f
    return force


def oracle(opts, period, feed, cut_on):
    """The sampled loop: t_k = k T, x_k, F_k and e_k, k = 0 .. periods - 1."""
    cut = Cut(feed, cut_on)
    law = sliding_law(opts, period) if opts.mode == "law" else pid_law(period)
    periods = round(opts.duration / period)
    x, v = 0.0, AMPLITUDE * OMEGA  # on the reference: x_ref(0) = 0, v_ref(0) = A omega
    x_prev = None
    integral = 0.0
    xs, fs, es = np.empty(periods), np.empty(periods), np.empty(periods)

    def rhs(t, y, force):
        return [y[1], (force - DAMPING * y[1] - cut.force(t)) / MASS]

    for k in range(periods):
        t = k * period
        x_ref = AMPLITUDE * math.sin(OMEGA * t)
        v_ref = AMPLITUDE * OMEGA * math.cos(OMEGA * t)
        a_ref = -AMPLITUDE * OMEGA * OMEGA * math.sin(OMEGA * t)
        v_hat = v if k == 0 else (x - x_prev) / period
        e = x_ref - x
        force = law(a_ref, v_ref, e, v_ref - v_hat, integral, v_hat)
        force = max(-FORCE_LIMIT, min(FORCE_LIMIT, force))
        xs[k], fs[k], es[k] = x, force, e
        integral += e * period
        x_prev = x
        # Hold F over [t_k, t_{k+1}), restarting at each corner of F_d.
        t_end = (k + 1) * period
        knots = [t] + cut.corners(t, t_end) + [t_end]
        y = [x, v]
        for a, b in zip(knots, knots[1:]):
            sol = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-12, atol=1e-16, args=(force,))
            if not sol.success:
                raise RuntimeError(sol.message)
            y = sol.y[:, -1]
        x, v = float(y[0]), float(y[1])
    return np.arange(periods) * period, xs, fs, es


def deviation(opts, substeps, cut_on, reference):
    t_ref, x_ref, f_ref = reference[:3]
    t, x, f = run_smcsim(opts, substeps, cut_on)
    if len(t) != len(t_ref) or np.max(np.abs(t - t_ref)) > 1e-12:
        raise SystemExit(f"smcsim wrote {len(t)} samples, the oracle has {len(t_ref)} (or the times differ)")
    dx = np.max(np.abs(x - x_ref)) / np.max(np.abs(x_ref))
    df = np.max(np.abs(f - f_ref)) / np.max(np.abs(f_ref))
    return dx, df


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("mode", choices=["compare", "converge", "exact", "law"])
    p.add_argument("--smcsim", default="smcsim")
    p.add_argument("--period", type=float, default=1e-4)
    p.add_argument("--substeps", default=None)
    p.add_argument("--feed", type=float, default=1.08, help="mm/min (smcsim's default 1.08)")
    p.add_argument("--no-cut", action="store_true")
    p.add_argument("--tol", type=float, default=None)
    p.add_argument("--ftol", type=float, default=1e-4, help="compare: bound on F's max relative deviation")
    p.add_argument("--effect-share", type=float, default=1e-3,
                   help="compare: bound on x's deviation over the cut's effect on x")
    p.add_argument("--duration", type=float, default=0.2, help="s")
    p.add_argument("--controller", choices=["smc", "sta"], default="smc", help="law: the sliding-mode law")
    p.add_argument("--bracket", choices=["surface", "printed"], default="surface",
                   help="law: the equivalent control from eq. 6, or the bracket printed in eq. 8-9")
    p.add_argument("--seed-sign", action="store_true", help="law: switch with -Lambda sign(S) as printed")
    p.add_argument("--Lambda", type=float, default=400.0)
    p.add_argument("--alpha", type=float, default=200.0)
    p.add_argument("--beta", type=float, default=200.0)
    p.add_argument("--units", choices=["mm", "m"], default="mm", help="law: the gains' length unit, as smcsim's")
    p.add_argument("--min-order", type=float, default=1.8)
    p.add_argument("--max-order", type=float, default=2.3)
    opts = p.parse_args()
    failed = False

    if opts.mode in ("law", "compare"):  # one run against the oracle
        substeps = int(opts.substeps or 10)
        tol = opts.tol if opts.tol is not None else 1e-6
        reference = oracle(opts, opts.period, opts.feed, not opts.no_cut)
        dx, df = deviation(opts, substeps, not opts.no_cut, reference)
        ok_x, ok_f = dx <= tol, df <= opts.ftol
        verdict = f"max relative deviation x {dx:.3e} (<= {tol:g}: {ok_x}), F {df:.3e} (<= {opts.ftol:g}: {ok_f})"
    if opts.mode == "law":
        # The other bracket must land far from this oracle, or the check could not tell them apart.
        this = opts.bracket
        opts.bracket = "printed" if this == "surface" else "surface"
        other_dx, _ = deviation(opts, substeps, not opts.no_cut, reference)
        opts.bracket = this
        ok_other = other_dx >= 100 * tol
        print(f"{opts.controller}, {opts.bracket} bracket, sign {'-' if opts.seed_sign else '+'}, units {opts.units}, "
              f"{opts.duration:g} s at T {opts.period:g} s: {verdict}; the other bracket's x {other_dx:.3e} "
              f"(>= {100 * tol:g}: {ok_other}); oracle max |e| {np.max(np.abs(reference[3])) * 1e3:.4g} mm")
        failed = not (ok_x and ok_f and ok_other)
    elif opts.mode == "compare":
        # How much the cut moves the axis, to show the comparison can see it.
        effect = 0.0
        if not opts.no_cut:
            x_free = oracle(opts, opts.period, opts.feed, False)[1]
            effect = np.max(np.abs(reference[1] - x_free)) / np.max(np.abs(reference[1]))
        # The cut moves x by only ~1e-5 of its range, so the deviation must
        # also be small against that effect (a 2 % error in F_d is 3e-7 of x,
        # under 1e-6, but 2e-2 of the effect); F amplifies x's deviation by
        # k_d / T through the differenced velocity, hence its looser bound.
        ok_effect = opts.no_cut or dx <= opts.effect_share * effect
        print(f"T {opts.period:g} s, {substeps} substeps, cut {'off' if opts.no_cut else 'on'}: {verdict}; "
              f"the cut moves x by {effect:.3e}, deviation / effect {dx / effect if effect else 0:.3e} "
              f"(<= {opts.effect_share:g}: {ok_effect})")
        failed = not (ok_x and ok_effect and ok_f)
    elif opts.mode == "converge":
        counts = [int(s) for s in (opts.substeps or "1,2,4,8").split(",")]
        reference = oracle(opts, opts.period, opts.feed, True)
        errors = [deviation(opts, n, True, reference)[0] for n in counts]
        for n, err in zip(counts, errors):
            print(f"T {opts.period:g} s, {n} substeps: max relative deviation of x {err:.4e}")
        for i in range(1, len(counts)):
            order = math.log(errors[i - 1] / errors[i]) / math.log(counts[i] / counts[i - 1])
            ok = opts.min_order <= order <= opts.max_order
            print(f"  {counts[i - 1]} -> {counts[i]} substeps: error ratio {errors[i - 1] / errors[i]:.3f}, "
                  f"observed order {order:.3f} {'ok' if ok else 'OUT OF RANGE'} "
                  f"[{opts.min_order}, {opts.max_order}]")
            failed = failed or not ok
    else:
        counts = [int(s) for s in (opts.substeps or "1,2,4,8").split(",")]
        tol = opts.tol if opts.tol is not None else 1e-10
        reference = oracle(opts, opts.period, opts.feed, False)
        for n in counts:
            dx, df = deviation(opts, n, False, reference)
            ok = dx <= tol
            print(f"no cut, T {opts.period:g} s, {n} substeps: max relative deviation x {dx:.3e}, F {df:.3e} "
                  f"{'ok' if ok else 'ABOVE'} {tol:g}")
            failed = failed or not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
