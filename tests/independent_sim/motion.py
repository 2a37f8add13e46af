#!/usr/bin/python3
"""Realistic feed-axis motion for the independent simulator.

* every move is a trapezoidal (or triangular) velocity profile with a finite
  acceleration, stored as constant-acceleration phases;
* a moving-state run: cycle 0 (cold reference) at t = 0, reciprocating
  warm-up strokes over a range at a feed, interrupted every `interval_s` by an
  ISO 230-2 style bidirectional measurement cycle (targets with irregular
  spacing, dwell before each reading, overrun of a few mm past the end targets
  before reversing), then a cool-down in which the axis stands still except
  for the measurement cycles;
* motor torque = Coulomb + viscous * omega + inertia * d(omega)/dt (+ noise
  where it is sampled), so it spikes at every reversal.
"""
import math
import os
import sys

for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")   # one core

import numpy as np  # imported after screwsim, which makes sure numpy is there


class Programme:
    """Motion as constant-acceleration phases plus the interferometer readings."""

    def __init__(self, x0):
        self.t = 0.0
        self.x = float(x0)
        self.phases = []      # (t0, dur, x0, v0, a)   mm, mm/s, mm/s^2
        self.readings = []    # (t, cycle, target_mm, '+'/'-')
        self.cycles = []      # (cycle, t_start, t_end)

    # -- primitives -------------------------------------------------------
    def _phase(self, dur, v0, a):
        if dur <= 0:
            return
        self.phases.append((self.t, dur, self.x, v0, a))
        self.x = self.x + v0 * dur + 0.5 * a * dur * dur
        self.t += dur

    def dwell(self, dur):
        self._phase(dur, 0.0, 0.0)

    def move_to(self, x_to, feed_mm_min, acc_mm_s2):
        d = x_to - self.x
        if abs(d) < 1e-9:
            return
        sgn = 1.0 if d > 0 else -1.0
        d = abs(d)
        v = feed_mm_min / 60.0
        a = acc_mm_s2
        t_acc = v / a
        d_acc = 0.5 * a * t_acc * t_acc
        if 2 * d_acc >= d:          # triangular profile
            t_acc = math.sqrt(d / a)
            self._phase(t_acc, 0.0, sgn * a)
            self._phase(t_acc, sgn * a * t_acc, -sgn * a)
        else:
            self._phase(t_acc, 0.0, sgn * a)
            self._phase((d - 2 * d_acc) / v, sgn * v, 0.0)
            self._phase(t_acc, sgn * v, -sgn * a)
        self.x = x_to  # remove round-off

    # -- ISO 230-2 style measurement cycle ---------------------------------
    def measurement_cycle(self, cycle, targets, feed, acc, dwell_s, overrun_mm, at_start=False):
        """Bidirectional pass. With at_start the axis already sits at the first
        target (approached from below before logging began) and the first
        reading is taken at once (cycle 0 at time 0)."""
        t_start = self.t
        if not at_start:
            self.move_to(targets[0] - overrun_mm, feed, acc)
        for i, tg in enumerate(targets):
            if at_start and i == 0:
                self.readings.append((self.t, cycle, tg, "+"))
                continue
            self.move_to(tg, feed, acc)
            self.dwell(dwell_s)
            self.readings.append((self.t, cycle, tg, "+"))
        self.move_to(targets[-1] + overrun_mm, feed, acc)
        for tg in targets[::-1]:
            self.move_to(tg, feed, acc)
            self.dwell(dwell_s)
            self.readings.append((self.t, cycle, tg, "-"))
        self.move_to(targets[0] - overrun_mm, feed, acc)
        self.cycles.append((cycle, t_start, self.t))

    # -- evaluation -------------------------------------------------------
    def arrays(self):
        ph = np.array(self.phases, dtype=float)
        return ph[:, 0], ph[:, 1], ph[:, 2], ph[:, 3], ph[:, 4]

    def evaluate(self, t):
        """Position (mm), velocity (mm/s), acceleration (mm/s^2) at times t."""
        t0, dur, x0, v0, a = self.arrays()
        t = np.asarray(t, dtype=float)
        i = np.clip(np.searchsorted(t0, t, side="right") - 1, 0, len(t0) - 1)
        tau = np.clip(t - t0[i], 0.0, dur[i])
        pos = x0[i] + v0[i] * tau + 0.5 * a[i] * tau * tau
        inside = (t >= t0[i]) & (t < t0[i] + dur[i])
        vel = np.where(inside, v0[i] + a[i] * tau, 0.0)
        acc = np.where(inside, a[i], 0.0)
        return pos, vel, acc

    def motion_rows(self):
        """(start_s, end_s, from_mm, to_mm, feed_mm_min) rows, one per phase
        (accelerations become their own rows, with their mean feed)."""
        rows = []
        for t0, dur, x0, v0, a in self.phases:
            x1 = x0 + v0 * dur + 0.5 * a * dur * dur
            feed = (x1 - x0) / dur * 60.0 if dur > 0 else 0.0
            rows.append((t0, t0 + dur, x0, x1, feed))
        return rows

    @property
    def end_time(self):
        return self.t


def iso_targets(travel, n, rng, max_shift=0.08):
    """n targets over the travel, interior ones shifted by < 10 % of the interval
    (ISO 230-2 irregular spacing); end targets inside the travel."""
    lo, hi = travel
    base = np.linspace(lo, hi, n)
    step = (hi - lo) / (n - 1)
    shift = rng.uniform(-max_shift, max_shift, n) * step
    shift[0] = abs(shift[0]) * 0.3
    shift[-1] = -abs(shift[-1]) * 0.3
    return np.round(base + shift, 3)


def moving_run(targets, feed, rng_mm, warmup_s, cooldown_s, interval_s, meas_feed,
               acc_mm_s2, dwell_s, overrun_mm, interval_jitter_s=0.0, rng=None):
    """Build the programme of one moving-state run."""
    p = Programme(targets[0])
    cyc = 0
    p.measurement_cycle(cyc, targets, meas_feed, acc_mm_s2, dwell_s, overrun_mm, at_start=True)
    cyc += 1
    lo, hi = rng_mm
    next_meas = interval_s
    while True:
        p.move_to(lo, feed, acc_mm_s2)
        # reciprocate until a measurement is due (finish the current stroke pair)
        while p.t < min(next_meas, warmup_s):
            p.move_to(hi, feed, acc_mm_s2)
            p.move_to(lo, feed, acc_mm_s2)
        p.measurement_cycle(cyc, targets, meas_feed, acc_mm_s2, dwell_s, overrun_mm)
        cyc += 1
        if p.t >= warmup_s:
            break
        j = rng.uniform(-interval_jitter_s, interval_jitter_s) if (rng is not None and interval_jitter_s) else 0.0
        next_meas += interval_s + j
    warm_end = p.t
    next_meas = warm_end + interval_s
    while next_meas <= warm_end + cooldown_s + 1e-6:
        p.dwell(next_meas - p.t)
        p.measurement_cycle(cyc, targets, meas_feed, acc_mm_s2, dwell_s, overrun_mm)
        cyc += 1
        next_meas += interval_s
    p.dwell(30.0)   # axis at rest until logging stops
    return p, warm_end


class Drive:
    """Servo drive / mechanics for the torque signal."""

    def __init__(self, lead_mm, coulomb_Nm=0.8, viscous_Nms=0.004, j_motor=1.5e-3,
                 screw_length_mm=900.0, screw_diameter_mm=40.0, table_kg=300.0, v_eps_mm_s=2.0):
        self.lead_mm = lead_mm
        self.coulomb = coulomb_Nm
        self.viscous = viscous_Nms
        j_screw = math.pi / 32.0 * 7850.0 * screw_length_mm * 1e-3 * (screw_diameter_mm * 1e-3) ** 4
        j_table = table_kg * (lead_mm * 1e-3 / (2 * math.pi)) ** 2
        self.inertia = j_motor + j_screw + j_table
        self.v_eps = v_eps_mm_s

    def torque(self, vel_mm_s, acc_mm_s2):
        k = 2 * math.pi / self.lead_mm
        om = k * vel_mm_s
        dom = k * acc_mm_s2
        return self.coulomb * np.tanh(vel_mm_s / self.v_eps) + self.viscous * om + self.inertia * dom


def nut_heat_per_step(model, pos_f, power_f, dt_f, dt, t_end):
    """Step-averaged nut heat per cell (W), from fine midpoint samples of the nut
    centre position and friction power.  Each sub-sample deposits
    power * (overlap of the nut footprint with the cell) / nut length."""
    r = int(round(dt / dt_f))
    assert abs(r * dt_f - dt) < 1e-9, "dt must be a multiple of dt_f"
    N = int(math.ceil(t_end / dt - 1e-9))
    need = N * r
    pos = np.asarray(pos_f, dtype=float)[:need]
    pw = np.asarray(power_f, dtype=float)[:need]
    if len(pos) < need:
        pos = np.concatenate([pos, np.full(need - len(pos), pos[-1] if len(pos) else 0.0)])
        pw = np.concatenate([pw, np.zeros(need - len(pw))])
    half = 0.5 * model.s.nut_length_mm
    out = np.zeros((N, model.n))
    moving = pw > 0
    chunk = 4000 * r
    for s0 in range(0, need, chunk):
        sl = slice(s0, min(need, s0 + chunk))
        p, w = pos[sl], pw[sl]
        mv = moving[sl]
        if not mv.any():
            continue
        W = np.zeros((len(p), model.n))
        W[mv] = model.overlap_mm(p[mv] - half, p[mv] + half) * (w[mv] / (2 * half))[:, None]
        out[s0 // r:(sl.stop) // r] = W.reshape(-1, r, model.n).sum(1) * (dt_f / dt)
    return out
