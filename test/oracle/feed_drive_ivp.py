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
DURATION = 0.2


def smcsim_args(opts, substeps, cut):
    args = [opts.smcsim, "--controller", "pid", "--kp", repr(KP), "--ki", repr(KI), "--kd", repr(KD), "--pid-ff", "1",
            "--mass", repr(MASS), "--damping", repr(DAMPING),
            "--mass-estimate", repr(MASS_HAT), "--damping-estimate", repr(DAMPING_HAT),
            "--kt", "2", "--ka", "50", "--voltage-limit", "10",
            "--reference", "sine", "--amplitude", "1", "--omega", repr(OMEGA),
            "--teeth", str(TEETH), "--tool-diameter", repr(DIAMETER), "--spindle", repr(SPINDLE),
            "--axial-depth", repr(AXIAL), "--feed", repr(opts.feed), "--ktc", repr(KTC), "--krc", repr(KRC),
            "--kte", "0", "--kre", "0",
            "--encoder", "0", "--position-filter", "0", "--velocity-filter", "0",
            "--duration", repr(DURATION), "--period", repr(opts.period), "--substeps", str(substeps),
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


def oracle(period, feed, cut_on):
    """The sampled loop: x_k and F_k at t_k = k T, k = 0 .. periods - 1."""
    cut = Cut(feed, cut_on)
    periods = round(DURATION / period)
    x, v = 0.0, AMPLITUDE * OMEGA  # on the reference: x_ref(0) = 0, v_ref(0) = A omega
    x_prev = None
    integral = 0.0
    xs, fs = np.empty(periods), np.empty(periods)

    def rhs(t, y, force):
        return [y[1], (force - DAMPING * y[1] - cut.force(t)) / MASS]

    for k in range(periods):
        t = k * period
        x_ref = AMPLITUDE * math.sin(OMEGA * t)
        v_ref = AMPLITUDE * OMEGA * math.cos(OMEGA * t)
        a_ref = -AMPLITUDE * OMEGA * OMEGA * math.sin(OMEGA * t)
        v_hat = v if k == 0 else (x - x_prev) / period
        e = x_ref - x
        force = MASS_HAT * a_ref + DAMPING_HAT * v_ref + KP * e + KI * integral + KD * (v_ref - v_hat)
        force = max(-FORCE_LIMIT, min(FORCE_LIMIT, force))
        xs[k], fs[k] = x, force
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
    return np.arange(periods) * period, xs, fs


def deviation(opts, substeps, cut_on, reference):
    t_ref, x_ref, f_ref = reference
    t, x, f = run_smcsim(opts, substeps, cut_on)
    if len(t) != len(t_ref) or np.max(np.abs(t - t_ref)) > 1e-12:
        raise SystemExit(f"smcsim wrote {len(t)} samples, the oracle has {len(t_ref)} (or the times differ)")
    dx = np.max(np.abs(x - x_ref)) / np.max(np.abs(x_ref))
    df = np.max(np.abs(f - f_ref)) / np.max(np.abs(f_ref))
    return dx, df


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("mode", choices=["compare", "converge", "exact"])
    p.add_argument("--smcsim", default="smcsim")
    p.add_argument("--period", type=float, default=1e-4)
    p.add_argument("--substeps", default=None)
    p.add_argument("--feed", type=float, default=1.08, help="mm/min (smcsim's default 1.08)")
    p.add_argument("--no-cut", action="store_true")
    p.add_argument("--tol", type=float, default=None)
    p.add_argument("--ftol", type=float, default=1e-4, help="compare: bound on F's max relative deviation")
    p.add_argument("--effect-share", type=float, default=1e-3,
                   help="compare: bound on x's deviation over the cut's effect on x")
    p.add_argument("--min-order", type=float, default=1.8)
    p.add_argument("--max-order", type=float, default=2.3)
    opts = p.parse_args()
    failed = False

    if opts.mode == "compare":
        substeps = int(opts.substeps or 10)
        tol = opts.tol if opts.tol is not None else 1e-6
        reference = oracle(opts.period, opts.feed, not opts.no_cut)
        dx, df = deviation(opts, substeps, not opts.no_cut, reference)
        # How much the cut moves the axis, to show the comparison can see it.
        effect = 0.0
        if not opts.no_cut:
            _, x_free, _ = oracle(opts.period, opts.feed, False)
            effect = np.max(np.abs(reference[1] - x_free)) / np.max(np.abs(reference[1]))
        # The cut moves x by only ~1e-5 of its range, so the deviation must
        # also be small against that effect (a 2 % error in F_d is 3e-7 of x,
        # under 1e-6, but 2e-2 of the effect); F amplifies x's deviation by
        # k_d / T through the differenced velocity, hence its looser bound.
        ok_x, ok_effect, ok_f = dx <= tol, opts.no_cut or dx <= opts.effect_share * effect, df <= opts.ftol
        print(f"T {opts.period:g} s, {substeps} substeps, cut {'off' if opts.no_cut else 'on'}: "
              f"max relative deviation x {dx:.3e} (<= {tol:g}: {ok_x}), F {df:.3e} (<= {opts.ftol:g}: {ok_f}); "
              f"the cut moves x by {effect:.3e}, deviation / effect {dx / effect if effect else 0:.3e} "
              f"(<= {opts.effect_share:g}: {ok_effect})")
        failed = not (ok_x and ok_effect and ok_f)
    elif opts.mode == "converge":
        counts = [int(s) for s in (opts.substeps or "1,2,4,8").split(",")]
        reference = oracle(opts.period, opts.feed, True)
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
        reference = oracle(opts.period, opts.feed, False)
        for n in counts:
            dx, df = deviation(opts, n, False, reference)
            ok = dx <= tol
            print(f"no cut, T {opts.period:g} s, {n} substeps: max relative deviation x {dx:.3e}, F {df:.3e} "
                  f"{'ok' if ok else 'ABOVE'} {tol:g}")
            failed = failed or not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
