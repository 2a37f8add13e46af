#!/usr/bin/python3
"""Independent ball-screw thermal simulator (finite volumes, non-uniform grid).

Physics as docs/physics.md states it, written without looking at
DriftLab's own implementation:

    rho c A dT/dt = k A d2T/dx2 - h P (T - T_amb(t)) + q_nut(x,t) + q_bearings(x,t)

Discretisation (deliberately different from a uniform-grid implicit FDM):
  * cell-centred finite volumes on a NON-UNIFORM grid, clustered towards both
    ends of the screw (bearing seats), face positions
    x = x0 + L (xi - a sin(2 pi xi) / (2 pi)), xi uniform in [0, 1];
  * conductances between cell centres, adiabatic screw ends;
  * midpoint Crank-Nicolson in time (step-averaged sources, convection
    coefficient and ambient per step), one tridiagonal (banded) solve per step,
    several right-hand sides at once so responses can be superposed;
  * the moving nut: the motion is evaluated on a fine sub-grid (midpoint
    rule); at each sub-point the nut footprint [p - l/2, p + l/2] is
    intersected exactly with every cell, and the overlap x power is averaged
    over the step.  Heat per cell therefore follows the time the nut covered
    it, whatever the stroke speed.

Thermal error E(x, t) = int_{x0}^{x} alpha (T(s,t) - T(s,0)) ds in um, with
exact partial-cell integration at x.

Run `python3 screwsim.py --selfcheck` for the analytic checks.
"""
import math
import os
import sys

for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")   # one core

try:
    import numpy as np
    from scipy.linalg import solve_banded
    from scipy.special import erfc
except ImportError:  # pyenv python without the Debian packages: re-run with Debian's
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3" \
            and not os.environ.get("SCREWSIM_REEXEC"):
        os.environ["SCREWSIM_REEXEC"] = "1"
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise


class Screw:
    """Screw geometry and material, units as in campaign.json (mm, SI)."""

    def __init__(self, length_mm=900.0, diameter_mm=40.0, lead_mm=10.0, fixed_end_mm=-40.0,
                 alpha_per_K=11.5e-6, density=7850.0, specific_heat=460.0, conductivity=45.0,
                 nut_length_mm=80.0):
        self.length_mm = float(length_mm)
        self.diameter_mm = float(diameter_mm)
        self.lead_mm = float(lead_mm)
        self.fixed_end_mm = float(fixed_end_mm)
        self.alpha = float(alpha_per_K)
        self.rho = float(density)
        self.cp = float(specific_heat)
        self.k = float(conductivity)
        self.nut_length_mm = float(nut_length_mm)

    @property
    def area_m2(self):
        return math.pi * (self.diameter_mm * 1e-3) ** 2 / 4.0

    @property
    def perimeter_m(self):
        return math.pi * self.diameter_mm * 1e-3

    @property
    def free_end_mm(self):
        return self.fixed_end_mm + self.length_mm

    def omega(self, v_mm_s):
        """Screw angular speed (rad/s) for a table speed in mm/s."""
        return 2.0 * math.pi * np.asarray(v_mm_s) / self.lead_mm


class FVModel:
    """Finite-volume model of one screw on a non-uniform grid."""

    def __init__(self, screw, n_cells=64, cluster=0.6):
        self.s = screw
        n = int(n_cells)
        xi = np.linspace(0.0, 1.0, n + 1)
        frac = xi - cluster * np.sin(2.0 * np.pi * xi) / (2.0 * np.pi)
        self.faces_mm = screw.fixed_end_mm + screw.length_mm * frac
        self.faces_mm[0] = screw.fixed_end_mm
        self.faces_mm[-1] = screw.free_end_mm
        self.xc_mm = 0.5 * (self.faces_mm[1:] + self.faces_mm[:-1])
        self.dx_mm = np.diff(self.faces_mm)
        self.n = n
        dx = self.dx_mm * 1e-3
        A, P = screw.area_m2, screw.perimeter_m
        self.C = screw.rho * screw.cp * A * dx               # J/K per cell
        self.Gk = screw.k * A / (np.diff(self.xc_mm) * 1e-3)  # W/K between centres
        self.Pdx = P * dx                                    # m^2 convective area per cell

    # ---- geometry helpers -------------------------------------------------
    def overlap_mm(self, a_mm, b_mm):
        """Length (mm) of [a, b] inside each cell; a, b arrays (m,) -> (m, n)."""
        a = np.asarray(a_mm, dtype=float)[:, None]
        b = np.asarray(b_mm, dtype=float)[:, None]
        lo = np.maximum(a, self.faces_mm[None, :-1])
        hi = np.minimum(b, self.faces_mm[None, 1:])
        return np.clip(hi - lo, 0.0, None)

    def region_weights(self, a_mm, b_mm):
        """Weights (sum 1) spreading a heat input uniformly over [a, b] clipped to the screw."""
        a = max(a_mm, self.faces_mm[0])
        b = min(b_mm, self.faces_mm[-1])
        w = self.overlap_mm([a], [b])[0]
        return w / w.sum()

    def probe(self, T, x_mm):
        """Screw temperature at x (linear between cell centres, flat in the end half-cells).
        T: (..., n) -> (...)."""
        x = float(np.clip(x_mm, self.xc_mm[0], self.xc_mm[-1]))
        j = int(np.searchsorted(self.xc_mm, x) - 1)
        j = min(max(j, 0), self.n - 2)
        f = (x - self.xc_mm[j]) / (self.xc_mm[j + 1] - self.xc_mm[j])
        return (1.0 - f) * T[..., j] + f * T[..., j + 1]

    def footprint_mean(self, T, centre_mm):
        """Mean temperature under a nut centred at centre_mm (rows of T matched to centres)."""
        half = 0.5 * self.s.nut_length_mm
        c = np.atleast_1d(centre_mm)
        w = self.overlap_mm(c - half, c + half)
        return (w * T).sum(-1) / w.sum(-1)

    def integral_weights(self, x_mm):
        """Weights w (mm) so that sum_i w_i f_i = int_{x0}^{x} f ds for cellwise-constant f."""
        x = np.atleast_1d(np.asarray(x_mm, dtype=float))
        return self.overlap_mm(np.full_like(x, self.faces_mm[0]), x)

    def thermal_error_um(self, dT, x_mm):
        """E(x) in um for temperature change profiles dT (..., n) at positions x (matched rows
        or a single profile for many x)."""
        W = self.integral_weights(x_mm)          # (m, n) in mm
        return self.s.alpha * (W * dT).sum(-1) * 1000.0

    # ---- time integration -------------------------------------------------
    def _banded(self, h, dt):
        """Banded (C/dt + K/2) and the tridiagonal K for convection coefficient h."""
        n = self.n
        Gh = h * self.Pdx
        diag = Gh.copy()
        diag[:-1] += self.Gk
        diag[1:] += self.Gk
        return diag, Gh

    def integrate(self, dt, h_steps, sources, tamb_steps, T0):
        """Midpoint Crank-Nicolson.

        dt          step (s)
        h_steps     (N,) convection coefficient per step (W/m^2K)
        sources     (N, n) or (N, n, k) heat per cell, step-averaged (W)
        tamb_steps  (N,) or (N, k) ambient per step (step midpoint) (degC)
        T0          (n,) or (n, k) initial temperatures
        returns     (N+1, n[, k]) temperatures at step boundaries
        """
        N = len(h_steps)
        src = np.asarray(sources, dtype=float)
        squeeze = src.ndim == 2
        if squeeze:
            src = src[:, :, None]
        k = src.shape[2]
        tamb = np.asarray(tamb_steps, dtype=float)
        if tamb.ndim == 1:
            tamb = np.repeat(tamb[:, None], k, axis=1)
        T = np.array(T0, dtype=float).reshape(self.n, -1) * np.ones((1, k))
        out = np.empty((N + 1, self.n, k))
        out[0] = T
        Cdt = self.C / dt
        Gk = self.Gk
        ab = np.zeros((3, self.n))
        last_h = None
        for i in range(N):
            h = h_steps[i]
            if h != last_h:
                diag, Gh = self._banded(h, dt)
                ab[0, 1:] = -0.5 * Gk
                ab[1] = Cdt + 0.5 * diag
                ab[2, :-1] = -0.5 * Gk
                last_h = h
            # (C/dt - K/2) T
            KT = diag[:, None] * T
            KT[:-1] -= Gk[:, None] * T[1:]
            KT[1:] -= Gk[:, None] * T[:-1]
            rhs = Cdt[:, None] * T - 0.5 * KT + src[i] + Gh[:, None] * tamb[i][None, :]
            T = solve_banded((1, 1), ab, rhs, overwrite_b=True, check_finite=False)
            out[i + 1] = T
        return out[:, :, 0] if squeeze else out

    def steady(self, h, source, tamb):
        diag, Gh = self._banded(h, 1.0)
        ab = np.zeros((3, self.n))
        ab[0, 1:] = -self.Gk
        ab[1] = diag
        ab[2, :-1] = -self.Gk
        return solve_banded((1, 1), ab, source + Gh * tamb)


def first_order_lag(u, dt, tau, y0=None):
    """Exact discrete first-order lag of a piecewise-constant input sampled every dt."""
    u = np.asarray(u, dtype=float)
    if tau <= 0:
        return u.copy()
    a = math.exp(-dt / tau)
    y = np.empty_like(u)
    prev = u[0] if y0 is None else y0
    # vectorised via scipy.signal.lfilter when available
    try:
        from scipy.signal import lfilter
        zi = np.array([a * prev])
        y, _ = lfilter([1.0 - a], [1.0, -a], u, zi=zi)
        return y
    except ImportError:  # pragma: no cover
        for i, v in enumerate(u):
            prev = a * prev + (1.0 - a) * v
            y[i] = prev
        return y


# ---------------------------------------------------------------------------
# self-check against analytic solutions
# ---------------------------------------------------------------------------
def selfcheck(verbose=True):
    ok = True
    results = []

    def report(name, err, tol):
        nonlocal ok
        good = err <= tol
        ok &= good
        results.append((name, err, tol, good))
        if verbose:
            print(f"  {'PASS' if good else 'FAIL'}  {name}: rel. error {err:.2e} (tol {tol:.0e})")

    s = Screw(length_mm=1000.0, diameter_mm=40.0, fixed_end_mm=0.0)
    m = FVModel(s, n_cells=120, cluster=0.6)
    A, P, k = s.area_m2, s.perimeter_m, s.k
    h = 12.0
    L = s.length_mm * 1e-3

    # 1. steady fin, heat Q into the first cell, adiabatic tip
    Q = 5.0
    src = np.zeros(m.n)
    src[0] = Q
    Ts = m.steady(h, src, 20.0) - 20.0
    mm = math.sqrt(h * P / (k * A))
    x = m.xc_mm * 1e-3
    ana = Q * np.cosh(mm * (L - x)) / (k * A * mm * math.sinh(mm * L))
    report("steady fin with convection (profile, max err / theta(0))",
           float(np.max(np.abs(Ts - ana)) / ana[0]), 2e-2)
    # energy balance of the steady state
    report("steady fin energy balance", abs(float((h * m.Pdx * Ts).sum()) - Q) / Q, 1e-9)
    # time stepping converges to the steady state
    tau = s.rho * s.cp * A / (h * P)
    dt = 20.0
    N = int(12 * tau / dt)
    Tt = m.integrate(dt, np.full(N, h), np.tile(src, (N, 1)), np.full(N, 20.0), np.full(m.n, 20.0))
    report("CN transient -> steady fin", float(np.max(np.abs(Tt[-1] - 20.0 - Ts)) / Ts[0]), 2e-3)

    # 2. lumped time constant: uniform source per length, uniform T
    q = 3.0  # W/m
    srcu = q * m.dx_mm * 1e-3
    for dt in (2.0, 60.0):
        N = int(round(3 * tau / dt))
        Tt = m.integrate(dt, np.full(N, h), np.tile(srcu, (N, 1)), np.full(N, 20.0), np.full(m.n, 20.0))
        t = np.arange(N + 1) * dt
        ana = q / (h * P) * (1 - np.exp(-t / tau))
        err = float(np.max(np.abs(Tt.mean(1) - 20.0 - ana)) / ana[-1])
        report(f"lumped time constant tau={tau:.0f} s (dt={dt:g} s)", err, 2e-3 if dt < 10 else 5e-3)

    # 3. semi-infinite rod under constant flux (h = 0, short time)
    Q = 10.0
    src = np.zeros(m.n)
    src[0] = Q
    t_end = 600.0
    dt = 1.0
    N = int(t_end / dt)
    Tt = m.integrate(dt, np.zeros(N), np.tile(src, (N, 1)), np.zeros(N), np.zeros(m.n))
    a_th = k / (s.rho * s.cp)
    qf = Q / A
    xx = m.xc_mm[:10] * 1e-3
    r = np.sqrt(a_th * t_end)
    ana = 2 * qf / k * (r / math.sqrt(math.pi) * np.exp(-xx ** 2 / (4 * r * r)) - xx / 2 * erfc(xx / (2 * r)))
    report("semi-infinite rod, constant flux (first 10 cells)", float(np.max(np.abs(Tt[-1, :10] - ana)) / ana[0]), 2e-2)
    report("semi-infinite rod energy", abs(float((m.C * Tt[-1]).sum()) - Q * t_end) / (Q * t_end), 1e-9)

    # 4. thermal error of a uniform temperature change
    dT = np.full(m.n, 2.0)
    xs = np.array([0.0, 123.4, 500.0, 999.0])
    E = m.thermal_error_um(dT, xs)
    exact = s.alpha * 2.0 * (xs - s.fixed_end_mm) * 1000.0
    report("thermal error, uniform dT", float(np.max(np.abs(E - exact)) / exact.max()), 1e-12)

    # 5. moving source: heat conservation and step independence
    from motion import nut_heat_per_step  # local module
    v = 200.0  # mm/s, strokes 300 mm -> 1.5 s per stroke
    tf = np.arange(0, 600, 0.05) + 0.025
    phase = (tf * v) % 600.0
    pos = 300 + np.where(phase < 300, phase, 600 - phase)
    om = np.full_like(tf, s.omega(v))
    dt_f = 0.05
    for dt in (2.0, 10.0):
        qs = nut_heat_per_step(m, pos, om * 0.08, dt_f, dt, len(tf) * dt_f)
        e_in = qs.sum() * dt
        exact = (om * 0.08).sum() * dt_f
        report(f"nut heat conserved over strokes (dt={dt:g} s)", abs(e_in - exact) / exact, 1e-9)
    # time-averaged footprint of a constant-speed triangular stroke = uniform
    # density of the nut centre over [300, 600] convolved with the footprint
    q2 = nut_heat_per_step(m, pos, om * 0.08, dt_f, 10.0, 600.0).mean(0)
    pp = np.linspace(300.0, 600.0, 30001)
    ref = m.overlap_mm(pp - 40.0, pp + 40.0).mean(0) / 80.0 * 0.08 * s.omega(v)
    report("moving nut: time-averaged heat profile vs exact stroke average (10 s steps)",
           float(np.abs(q2 - ref).max() / ref.max()), 2e-2)
    # 6. grid and step convergence on a warm-up: far-end thermal error
    def far_end_error(ncell, dt):
        mg = FVModel(s, n_cells=ncell, cluster=0.6)
        N = int(3600 / dt)
        w_nut = mg.region_weights(300, 700)
        w_b = mg.region_weights(0, 40)
        src = np.tile(6.0 * w_nut + 1.5 * w_b, (N, 1))
        T = mg.integrate(dt, np.full(N, h), src, np.full(N, 20.0), np.full(mg.n, 20.0))
        return float(mg.thermal_error_um(T[-1] - 20.0, [950.0])[0])
    e_ref = far_end_error(240, 1.0)
    e64 = far_end_error(64, 2.0)
    e64c = far_end_error(64, 10.0)
    if verbose:
        print(f"  info  far-end thermal error after 1 h: {e_ref:.3f} um (240 cells, 1 s), "
              f"{e64:.3f} um (64 cells, 2 s), {e64c:.3f} um (64 cells, 10 s)")
    report("grid/step convergence, 64 cells 2 s vs 240 cells 1 s", abs(e64 - e_ref) / abs(e_ref), 5e-3)
    report("step convergence, 64 cells 10 s vs 240 cells 1 s", abs(e64c - e_ref) / abs(e_ref), 5e-3)
    # 7. the widened suite's heat inputs (region at the fixed end, per-end bearing law, lags)
    from heat_regions import selfcheck_regions  # local module
    selfcheck_regions(report)
    return ok


if __name__ == "__main__":
    if "--selfcheck" in sys.argv:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        # Quiet when every check passes (a passing test prints nothing);
        # --verbose, or a failure, shows every check with its error.
        good = selfcheck(verbose="--verbose" in sys.argv)
        if not good:
            print("screwsim self-check FAILED")
            selfcheck(verbose=True)
        sys.exit(0 if good else 1)
    print(__doc__)
