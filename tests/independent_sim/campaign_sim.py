"""One campaign simulated run by run (screwsim's finite volumes driven by
motion's programme), with the hidden effects applied, and the base-model
refit that ranks two effects by what the base model cannot absorb."""
import json
import math
import os

import numpy as np

from screwsim import Screw, FVModel, first_order_lag  # noqa: F401
from motion import moving_run, iso_targets, Drive, nut_heat_per_step  # noqa: F401

from spec import *  # noqa: F401,F403
from heat_regions import fixed_end_region, bearing_weights, merged_sample_times  # noqa: F401

# ---------------------------------------------------------------------------
# simulation of one run
# ---------------------------------------------------------------------------
class RunSim:
    """Everything of one run that does not depend on the screw's thermal parameters."""

    def __init__(self, spec, run, model):
        self.spec, self.run, self.model = spec, run, model
        sc = spec["screw"]
        self.rng_motion = np.random.default_rng(run["seed"])
        prog, warm_end = moving_run(spec["targets"], run["feed_mm_min"], run["range_mm"], run["warmup_s"],
                                    run["cooldown_s"], run["interval_s"], run["meas_feed"], run["acc_mm_s2"],
                                    run["dwell_s"], run["overrun_mm"], interval_jitter_s=20.0,
                                    rng=self.rng_motion)
        self.prog, self.warm_end = prog, warm_end
        self.t_end = prog.end_time
        self.N = int(math.ceil(self.t_end / DT))
        r = int(round(DT / DT_F))
        self.r = r
        tf = (np.arange(self.N * r) + 0.5) * DT_F
        self.pos_f, self.vel_f, self.acc_f = prog.evaluate(tf)
        self.om_f = 2 * math.pi * np.abs(self.vel_f) / sc["lead_mm"]
        dr = spec["drive"]
        self.drive = Drive(sc["lead_mm"], dr["coulomb_Nm"], dr["viscous_Nms"], dr["j_motor"],
                           sc["length_mm"], sc["diameter_mm"], dr["table_kg"])
        self.torque_f = self.drive.torque(self.vel_f, self.acc_f)
        self.t_steps_mid = (np.arange(self.N) + 0.5) * DT
        self.t_bounds = np.arange(self.N + 1) * DT
        self.om_step = self.om_f.reshape(self.N, r).mean(1)
        self.tq2_step = (self.torque_f ** 2).reshape(self.N, r).mean(1)
        br = spec["bearing_region_mm"]
        self.w_fix = model.region_weights(sc["fixed_end_mm"], sc["fixed_end_mm"] + br)
        end = sc["fixed_end_mm"] + sc["length_mm"]
        self.w_free = model.region_weights(end - br, end)
        self.nut_unit = None

    def ambient(self, t):
        e, r = self.spec["env"], self.run
        t = np.asarray(t, dtype=float)
        return (e["room_C"] + e["amb_amp_K"] * np.sin(2 * np.pi * t / (e["amb_period_h"] * 3600) + r["amb_phase"])
                + r["amb_drift_K_h"] * t / 3600.0
                + e["amb_hvac_amp_K"] * np.sin(2 * np.pi * t / (e["amb_hvac_period_min"] * 60) + 1.7 * r["amb_phase"]))

    def nut_power_f(self, c_nut, exponent=None, omega_ref=None):
        if exponent is None:
            return c_nut * self.om_f
        return c_nut * omega_ref * (self.om_f / omega_ref) ** exponent

    def nut_heat(self, power_f):
        return nut_heat_per_step(self.model, self.pos_f, power_f, DT_F, DT, self.N * DT)

    def interp_steps(self, series, t):
        """Linear interpolation of a boundary series (N+1, ...) at times t."""
        x = np.clip(np.asarray(t) / DT, 0, self.N - 1e-9)
        i = np.floor(x).astype(int)
        f = (x - i)
        if series.ndim == 1:
            return (1 - f) * series[i] + f * series[i + 1]
        return (1 - f)[:, None] * series[i] + f[:, None] * series[i + 1]

    def interp_mid(self, series, t):
        return np.interp(t, self.t_steps_mid, series)


def lag_steps(u, tau, y0=None):
    return first_order_lag(u, DT, tau, y0)


def lag_bounds(u_steps, tau, y0=0.0):
    """First-order lag of a step-averaged input, returned at the step boundaries."""
    return np.r_[y0, first_order_lag(u_steps, DT, tau, y0)]


def simulate_campaign(spec, with_effects=True, keep_fields=False):
    """Simulate all runs.  Returns dict run_id -> data, and a summary."""
    sc = spec["screw"]
    screw = Screw(sc["length_mm"], sc["diameter_mm"], sc["lead_mm"], sc["fixed_end_mm"], sc["alpha_per_K"],
                  sc["density_kg_m3"], sc["specific_heat_J_kgK"], sc["conductivity_W_mK"], spec["nut_length_mm"])
    model = FVModel(screw, n_cells=N_CELLS, cluster=0.6)
    eff = spec["effects"] if with_effects else {}
    ph = spec["physics"]
    env = spec["env"]
    noise = spec["noise"]
    geo = spec["geometry"]
    out = {}
    # one reference speed for the exponent effect: the campaign's median warm-up speed
    om_ref = float(np.median([2 * math.pi * r["feed_mm_min"] / 60.0 / sc["lead_mm"] for r in spec["runs"]]))
    target_scatter = np.random.default_rng(spec["seed"] + 7).normal(0, geo["target_scatter_um"], len(spec["targets"]))
    scatter_of = {round(t, 3): s for t, s in zip(spec["targets"], target_scatter)}

    for run in spec["runs"]:
        rs = RunSim(spec, run, model)
        rng = np.random.default_rng(run["seed"] + 1)
        N = rs.N
        # --- heat sources (W per cell, step averaged) --------------------------
        if "nut_heat_exponent" in eff:
            n_exp = eff["nut_heat_exponent"]["n"]
            pw_f = rs.nut_power_f(ph["c_nut_W_s_rad"], n_exp, om_ref)
        else:
            pw_f = rs.nut_power_f(ph["c_nut_W_s_rad"])
        q_nut = rs.nut_heat(pw_f)
        Qb = ph["c_b_W_s_rad"] * rs.om_step
        if "bearing_asym" in eff:   # per-end bearing law: c_b*f_fix into the fixed end, c_b*f_free into the free end
            w_b, n_b = bearing_weights(rs.w_fix, rs.w_free, eff["bearing_asym"])
        else:
            w_b, n_b = rs.w_fix + rs.w_free, 2
        src = q_nut + Qb[:, None] * w_b[None, :]
        motor_loss = spec["drive"]["motor_loss_W_Nm2"] * rs.tq2_step   # total motor copper loss (W)
        if "motor_heat" in eff:
            me = eff["motor_heat"]
            q_m = lag_steps(me["k_W_per_Nm2"] * rs.tq2_step, me["tau_s"], 0.0)
            # into the fixed bearing's region, or spread over [a, b] mm from the fixed end (bearing + flange)
            w_m = rs.w_fix if "region_mm" not in me else fixed_end_region(model, sc["fixed_end_mm"], me["region_mm"])
            src = src + q_m[:, None] * w_m[None, :]
        else:
            q_m = np.zeros(N)
        if "forced_convection" in eff:
            fc = eff["forced_convection"]
            omm = (rs.om_f ** fc["m"]).reshape(N, rs.r).mean(1)
            h = ph["h0_W_m2K"] + fc["h1"] * omm
        else:
            h = np.full(N, ph["h0_W_m2K"])
        tamb_mid = rs.ambient(rs.t_steps_mid)
        T0 = np.full(model.n, float(rs.ambient(0.0)))
        T = model.integrate(DT, h, src, tamb_mid, T0)               # (N+1, n)

        # --- environment signals (step grid, noise-free) ------------------------
        p_mach = q_nut.sum(1) + n_b * Qb + motor_loss
        amb_b = rs.ambient(rs.t_bounds)
        air = (lag_steps(amb_b, env["air_tau_s"]) + env["air_offset_K"]
               + env["air_gain_K_W"] * lag_bounds(p_mach, env["air_heat_tau_s"])
               + env["air_hvac_amp_K"] * np.sin(2 * np.pi * rs.t_bounds / (env["air_hvac_period_min"] * 60) + run["hvac_phase"]))
        struct = (lag_steps(amb_b, env["struct_tau_s"]) + env["struct_offset_K"]
                  + env["struct_gain_K_W"] * lag_bounds(p_mach, env["struct_heat_tau_s"]))
        motor_T = (lag_steps(amb_b, 1800.0) + env["motor_R_K_W"] * lag_bounds(motor_loss, env["motor_tau_s"]))

        # --- sensors at sample times ---------------------------------------------
        smp = spec["sampling"]
        ts = np.arange(0.0, rs.t_end, smp["period_s"])
        ts[1:] += rng.uniform(-smp["jitter_s"], smp["jitter_s"], len(ts) - 1)
        ts = np.round(ts, 2)
        has_temp = has_axis = None
        if "axis_period_s" in smp:   # two devices merged: thermometers at period_s, axis columns at axis_period_s
            ts, has_temp, has_axis = merged_sample_times(ts, rs.t_end, smp, rng)
        pos_s, vel_s, acc_s = rs.prog.evaluate(ts)
        Ts = rs.interp_steps(T, ts)
        true = {}
        unlagged = {}
        lag_of = eff.get("sensor_lag", {})
        for ch in spec["channels"]:
            k = ch["kind"]
            if k == "nut":
                lag = eff.get("sensor_lag") if eff.get("sensor_lag", {}).get("channel") == ch["id"] else None
                if lag:
                    # the sensor sees the step-averaged footprint mean, lagged
                    Tm = 0.5 * (T[:-1] + T[1:])
                    half = 0.5 * spec["nut_length_mm"]
                    sig = np.empty(N)
                    for s0 in range(0, N, 2000):
                        s1 = min(N, s0 + 2000)
                        pf = rs.pos_f[s0 * rs.r:s1 * rs.r]
                        W = model.overlap_mm(pf - half, pf + half)
                        vals = (W * np.repeat(Tm[s0:s1], rs.r, axis=0)).sum(1) / W.sum(1)
                        sig[s0:s1] = vals.reshape(-1, rs.r).mean(1)
                    y = lag_steps(sig, lag["tau_s"])
                    true[k] = rs.interp_mid(y, ts)
                    unlagged[k] = rs.interp_mid(sig, ts)
                else:
                    true[k] = model.footprint_mean(Ts, pos_s)
            elif k in ("bfix", "bfree"):
                prof = model.probe(T, ch["position_mm"])
                if eff.get("sensor_lag", {}).get("channel") == ch["id"]:
                    unlagged[k] = rs.interp_steps(prof, ts)
                    prof = lag_steps(prof, eff["sensor_lag"]["tau_s"])
                true[k] = rs.interp_steps(prof, ts)
            elif k in ("amb", "air", "struct") and lag_of.get("channel") == ch["id"]:
                # a room, air or structure sensor that follows its medium with a first-order lag
                sig = {"amb": amb_b, "air": air, "struct": struct}[k]
                unlagged[k] = rs.interp_steps(sig, ts)
                true[k] = rs.interp_steps(lag_steps(sig, lag_of["tau_s"]), ts)
            elif k == "amb":
                true[k] = rs.ambient(ts)
            elif k == "air":
                true[k] = rs.interp_steps(air, ts)
            elif k == "struct":
                true[k] = rs.interp_steps(struct, ts)
            elif k == "motor":
                true[k] = rs.interp_steps(motor_T, ts)
            if eff.get("sensor_offset", {}).get("channel") == ch["id"]:
                true[k] = true[k] + eff["sensor_offset"]["offset_K"]
        meas = {k: v + rng.normal(0, noise["temp_K"], len(ts)) for k, v in true.items()}
        torque_s = rs.drive.torque(vel_s, acc_s) + rng.normal(0, noise["torque_Nm"], len(ts))
        if spec.get("torque_log") == "rms":
            # RMS of the drive torque since the previous sample, on the fine grid
            energy = np.r_[0.0, np.cumsum(rs.torque_f ** 2) * DT_F]
            k = np.minimum(np.round(ts / DT_F).astype(int), len(energy) - 1)
            span = np.maximum(np.diff(np.r_[0.0, ts]), DT_F)
            # (an RMS is never negative: the noise folds at zero)
            torque_s = np.abs(np.sqrt(np.maximum(np.diff(np.r_[0.0, energy[k]]), 0.0) / span)
                              + rng.normal(0, noise["torque_Nm"], len(ts)))

        # --- interferometer readings -------------------------------------------------
        rd = rs.prog.readings
        tr = np.array([x[0] for x in rd])
        xr = np.array([x[2] for x in rd])
        dr = np.array([1.0 if x[3] == "+" else -1.0 for x in rd])
        Tr = rs.interp_steps(T, tr)
        E = model.thermal_error_um(Tr - T[0][None, :], xr)
        g_lin = geo["lead_error_um_m"] * (xr - spec["travel_mm"][0]) / 1000.0
        g_per = geo["periodic_amp_um"] * np.sin(2 * np.pi * xr / geo["periodic_wavelength_mm"] + geo["periodic_phase"])
        g_sc = np.array([scatter_of[round(x, 3)] for x in xr])
        geo_err = g_lin + g_per + g_sc + 0.5 * geo["reversal_um"] * (-dr)   # '-' approach reads higher
        contrib = {}
        if "air_refraction" in eff:
            s = eff["air_refraction"]["s"]
            air_r = rs.interp_steps(air, tr)
            contrib["air_refraction"] = s * EDLEN_PPM_PER_K * (air_r - air[0]) * (xr + spec["dead_path_mm"]) * 1000.0
        if "frame_growth" in eff:
            fg = eff["frame_growth"]
            sl = lag_steps(struct, fg["tau_s"])
            contrib["frame_growth"] = fg["g_um_K"] * (rs.interp_steps(sl, tr) - struct[0])
        if "zero_step" in eff:
            zs = eff["zero_step"]
            st = zs["runs"].get(run["id"])
            contrib["zero_step"] = np.where(tr >= st[0], st[1], 0.0) if st else np.zeros(len(tr))
        if "growing_pitch" in eff:
            gp = eff["growing_pitch"]
            amp = gp["rate_um_h"] * np.minimum(tr, rs.warm_end) / 3600.0
            contrib["growing_pitch"] = amp * np.sin(2 * np.pi * xr / gp["wavelength_mm"] + gp["phase"])
        extra = sum(contrib.values()) if contrib else np.zeros(len(tr))
        dev = geo_err + E + extra + rng.normal(0, noise["laser_um"], len(tr))

        out[run["id"]] = {
            "rs": rs, "ts": ts, "pos_s": pos_s, "vel_s": vel_s, "torque_s": torque_s, "meas": meas,
            "readings": rd, "dev": dev, "E": E, "contrib": contrib, "tr": tr, "xr": xr,
            "true": true, "unlagged": unlagged, "has_temp": has_temp, "has_axis": has_axis,
            "air_b": air, "struct_b": struct,
            "summary": {
                "t_end_s": rs.t_end, "warmup_end_s": rs.warm_end, "cycles": len(rs.prog.cycles),
                "max_screw_rise_K": float((T - T[0][None, :]).max()),
                "max_nut_power_W": float(q_nut.sum(1).max()),
                "mean_nut_power_warmup_W": float(q_nut.sum(1)[: int(rs.warm_end / DT)].mean()),
                "max_motor_heat_W": float(q_m.max()),
                "h_range_W_m2K": [float(h.min()), float(h.max())],
                "far_end_thermal_error_max_um": float(np.max(model.thermal_error_um(
                    T - T[0][None, :], np.full(N + 1, spec["travel_mm"][1])))),
                "thermal_error_rms_um": float(np.sqrt(np.mean(E ** 2))),
                "air_range_K": float(air.max() - air.min()),
                "struct_range_K": float(struct.max() - struct.min()),
            },
        }
        if keep_fields:
            out[run["id"]]["T"] = T
    return out


# ---------------------------------------------------------------------------
# base-model refit (for ranking effects by what the base model cannot absorb)
# ---------------------------------------------------------------------------
def base_refit_residual(spec, target_dev, h_factors=(0.55, 0.7, 0.85, 1.0, 1.2, 1.45, 1.75, 2.1), extra=None,
                        extra_nonneg=False):
    """Fit c_nut, c_b (linear, >= 0) and h (grid) of the BASE model to the thermal error
    part of target_dev (dict run -> deviations, cycle-0 referenced inside) and return
    the RMS residual (um) and the parameters.  Uses the truth's ambient.
    extra: optional dict run -> (readings, m) further columns of free sign (a candidate's
    output shapes, e.g. an Edlen term of a logged sensor), fitted with the base; with
    extra_nonneg their coefficients are >= 0 (a heat input)."""
    sc = spec["screw"]
    screw = Screw(sc["length_mm"], sc["diameter_mm"], sc["lead_mm"], sc["fixed_end_mm"], sc["alpha_per_K"],
                  sc["density_kg_m3"], sc["specific_heat_J_kgK"], sc["conductivity_W_mK"], spec["nut_length_mm"])
    model = FVModel(screw, n_cells=40, cluster=0.6)
    prep = []
    for run in spec["runs"]:
        rs = RunSim(spec, run, model)
        qn = rs.nut_heat(rs.nut_power_f(1.0))
        qb = rs.om_step[:, None] * (rs.w_fix + rs.w_free)[None, :]
        src = np.stack([qn, qb, np.zeros_like(qn)], axis=2)
        tamb = np.stack([np.full(rs.N, 20.0), np.full(rs.N, 20.0), rs.ambient(rs.t_steps_mid)], axis=1)
        T0 = np.stack([np.full(model.n, 20.0), np.full(model.n, 20.0), np.full(model.n, float(rs.ambient(0.0)))], 1)
        rd = rs.prog.readings
        tr = np.array([x[0] for x in rd])
        xr = np.array([x[2] for x in rd])
        key = [(x[2], x[3]) for x in rd]
        cyc = np.array([x[1] for x in rd])
        y = np.asarray(target_dev[run["id"]], dtype=float)
        ref = {k: y[i] for i, k in enumerate(key) if cyc[i] == 0}
        y = y - np.array([ref[k] for k in key])
        prep.append((rs, src, tamb, T0, tr, xr, y))
    best = None
    for fct in h_factors:
        h = spec["physics"]["h0_W_m2K"] * fct
        A, b = [], []
        for rs, src, tamb, T0, tr, xr, y in prep:
            T = model.integrate(DT, np.full(rs.N, h), src, tamb, T0)   # (N+1, n, 3)
            cols = []
            for j in range(3):
                Tr = rs.interp_steps(T[:, :, j], tr)
                cols.append(model.thermal_error_um(Tr - T[0, :, j][None, :], xr))
            a_run = np.stack(cols[:2], 1)
            if extra is not None:
                ex = np.asarray(extra[rs.run["id"]], dtype=float).reshape(len(y), -1)
                a_run = np.concatenate([a_run, ex] if extra_nonneg else [a_run, ex, -ex], 1)
            A.append(a_run)
            b.append(y - cols[2])
        A = np.concatenate(A)
        b = np.concatenate(b)
        from scipy.optimize import nnls
        c, _ = nnls(A, b)
        res = b - A @ c
        rms = float(np.sqrt(np.mean(res ** 2)))
        if best is None or rms < best[0]:
            best = (rms, {"h": h, "c_nut": float(c[0]), "c_b": float(c[1])})
            if extra is not None:
                m = len(c) - 2 if extra_nonneg else (len(c) - 2) // 2
                best[1]["extra"] = [float(v) for v in (c[2:2 + m] if extra_nonneg else c[2:2 + m] - c[2 + m:])]
    return best


