"""Heat entering the screw elsewhere than DriftLab's candidates assume, and the
sample times of a logger that merges two devices; with their self-check
(run by `python3 screwsim.py --selfcheck`).

* fixed_end_region: a heat input (the motor's loss through the coupling and the
  bearing housing) spread uniformly over [a, b] mm from the fixed end, i.e. over
  the bearing pair and the flange, not into the end cell;
* bearing_weights: a per-end bearing law, Q_fix = f_fix c_b |omega| into the
  fixed bearing's region and Q_free = f_free c_b |omega| into the support
  bearing's, where the base model has f_fix = f_free = 1;
* merged_sample_times: thermometers every period_s and axis columns
  (position, feed, torque) every axis_period_s in one samples.csv, each row
  holding one device's cells (the row at 0 s holds both).
"""
import numpy as np


def fixed_end_region(model, fixed_end_mm, region_mm):
    """Weights (sum 1) of a heat input spread over [fixed_end + a, fixed_end + b]."""
    a, b = region_mm
    return model.region_weights(fixed_end_mm + a, fixed_end_mm + b)


def bearing_weights(w_fix, w_free, law):
    """Cell weights of the bearing heat per unit c_b|omega| and their total (W per W)."""
    f_fix, f_free = float(law["fix_factor"]), float(law["free_factor"])
    return f_fix * w_fix + f_free * w_free, f_fix + f_free


def merged_sample_times(ts_temp, t_end, smp, rng):
    """Union of the thermometer times (shifted by half a second after the first, so that
    the two devices never share an instant) and the axis device's times.
    Returns times, has_temp, has_axis (bool arrays)."""
    tt = np.array(ts_temp, dtype=float)
    tt[1:] += 0.5
    ta = np.arange(0.0, t_end, smp["axis_period_s"])
    ta[1:] += rng.uniform(-smp.get("axis_jitter_s", 0.0), smp.get("axis_jitter_s", 0.0), len(ta) - 1)
    ta = np.round(ta, 2)
    tt = np.round(tt, 2)
    t = np.concatenate([tt, ta[1:]])
    kind = np.concatenate([np.ones(len(tt), bool), np.zeros(len(ta) - 1, bool)])
    order = np.argsort(t, kind="stable")
    t, kind = t[order], kind[order]
    assert np.all(np.diff(t) > 0), "thermometer and axis times coincide"
    has_temp = kind.copy()
    has_axis = ~kind
    has_axis[0] = True       # the first row (0 s) carries both devices
    return t, has_temp, has_axis


# ---------------------------------------------------------------------------
# self-check
# ---------------------------------------------------------------------------
def selfcheck_regions(report):
    """report(name, rel_err, tol) as in screwsim.selfcheck."""
    from screwsim import Screw, FVModel, first_order_lag
    s = Screw(length_mm=1000.0, diameter_mm=40.0, fixed_end_mm=-90.0)
    m = FVModel(s, n_cells=64, cluster=0.6)
    # 1. heat over a region [8, 88] mm from the fixed end: weights, energy, where it lands
    w = fixed_end_region(m, s.fixed_end_mm, (8.0, 88.0))
    report("fixed-end region: weights sum to 1", abs(w.sum() - 1.0), 1e-12)
    centroid = float((w * m.xc_mm).sum())
    # exact centroid of a uniform input over [-82, -2] is -42 (cells cut exactly at the edges;
    # the centroid of a cut cell's share is its centre, so allow half a cell)
    cell = float(m.dx_mm[np.searchsorted(m.faces_mm, -42.0) - 1])
    report("fixed-end region: heat centred on the region (err / cell)", abs(centroid + 42.0) / cell, 0.5)
    report("fixed-end region: no heat outside it",
           float(w[(m.faces_mm[1:] <= -82.0) | (m.faces_mm[:-1] >= -2.0)].sum()), 1e-12)
    Q, dt, N = 4.0, 5.0, 720
    T = m.integrate(dt, np.zeros(N), np.tile(Q * w, (N, 1)), np.zeros(N), np.zeros(m.n))
    report("fixed-end region: energy stored = heat in (h = 0, 1 h)",
           abs(float((m.C * T[-1]).sum()) - Q * N * dt) / (Q * N * dt), 1e-9)
    # 2. per-end bearing law: steady energy balance with convection
    wf = m.region_weights(s.fixed_end_mm, s.fixed_end_mm + 35.0)
    wr = m.region_weights(s.free_end_mm - 35.0, s.free_end_mm)
    wb, nb = bearing_weights(wf, wr, {"fix_factor": 0.4, "free_factor": 3.0})
    Qb, h = 1.5, 11.0
    Ts = m.steady(h, Qb * wb, 20.0) - 20.0
    report("per-end bearing law: steady convective loss = 3.4 x c_b|omega|",
           abs(float((h * m.Pdx * Ts).sum()) - nb * Qb) / (nb * Qb), 1e-9)
    # the grid is mirror-symmetric, so the free end's rise is 3 x (a fixed-end input's rise at
    # its own end) + 0.4 x (its rise at the far end)
    T1 = m.steady(h, Qb * wf, 20.0) - 20.0
    report("per-end bearing law: free-end rise = 3.0 x own-end + 0.4 x far-end response (mirror)",
           abs(Ts[-1] - (3.0 * T1[0] + 0.4 * T1[-1])) / Ts[-1], 1e-9)
    # 3. a lagged heat input conserves energy and follows 1 - exp(-t/tau)
    tau = 1800.0
    u = np.r_[np.full(2000, 2.0), np.zeros(30000)]
    y = first_order_lag(u, 2.0, tau, 0.0)
    report("first-order lag conserves the heat (30 min lag, 18 h)", abs(y.sum() - u.sum()) / u.sum(), 1e-6)
    t = (np.arange(2000) + 1) * 2.0
    report("first-order lag step response", float(np.abs(y[:2000] - 2.0 * (1 - np.exp(-t / tau))).max()) / 2.0,
           2e-3)
    # 4. merged sampling: strictly increasing, each device on its own grid
    rng = np.random.default_rng(5)
    ts = np.round(np.arange(0.0, 600.0, 10.0) + np.r_[0.0, rng.uniform(-0.2, 0.2, 59)], 2)
    t, ht, ha = merged_sample_times(ts, 600.0, {"axis_period_s": 2.0, "axis_jitter_s": 0.05}, rng)
    report("merged sampling: 60 thermometer rows, 300 axis rows, one shared",
           abs(ht.sum() - 60) + abs(ha.sum() - 300) + abs((ht & ha).sum() - 1), 0)
    return True
