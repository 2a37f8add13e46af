"""Campaign specifications of the independent suite: geometry, physics,
environment, sampling, noise and channel names of one seeded campaign."""
import json
import math
import os

import numpy as np

from screwsim import Screw, FVModel, first_order_lag  # noqa: F401
from motion import moving_run, iso_targets, Drive, nut_heat_per_step  # noqa: F401

DT = 2.0          # solver step (s)
DT_F = 0.05       # motion sub-sample (s)
N_CELLS = 64
EDLEN_PPM_PER_K = -0.95e-6

# channel naming schemes: role/kind -> (id, location)
SCHEMES = [
    {"nut": ("TC01_nut", "nut flange, thermocouple"), "bfix": ("PT100_B1", "fixed bearing seat"),
     "bfree": ("PT100_B2", "support bearing seat"), "amb": ("Raumtemp", "hall, 1.5 m from machine"),
     "air": ("Luft_Laser", "laser beam path"), "struct": ("Bett_T", "machine bed"),
     "motor": ("Motor_T", "X motor housing")},
    {"nut": ("ch03", "nut housing"), "bfix": ("ch01", "fixed-end bearing block"),
     "bfree": ("ch02", "free-end support"), "amb": ("ch05", "room"),
     "air": ("ch06", "air near beam"), "struct": ("ch04", "base casting"), "motor": ("ch07", "motor flange")},
    {"nut": ("nut_flange", "nut flange"), "bfix": ("brg_fixed", "fixed bearing"),
     "bfree": ("brg_support", "support bearing"), "amb": ("room", "room air"),
     "air": ("beam_air", "beam path air"), "struct": ("column_T", "column foot"), "motor": ("motor_case", "servo motor")},
    {"nut": ("T1_Mutter", "Mutterflansch"), "bfix": ("T2_Festlager", "Festlager"),
     "bfree": ("T3_Loslager", "Loslager"), "amb": ("T_Halle", "Halle"),
     "air": ("T_Strahl", "Strahlengang"), "struct": ("T_Gestell", "Gestell"), "motor": ("T_Motor", "Motor")},
    {"nut": ("NUT", "nut"), "bfix": ("BRG_A", "bearing A (fixed)"), "bfree": ("BRG_B", "bearing B"),
     "amb": ("AMB", "ambient"), "air": ("AIR", "air"), "struct": ("STRUCT", "saddle"), "motor": ("MOT", "motor")},
]


# ---------------------------------------------------------------------------
# campaign specification
# ---------------------------------------------------------------------------
def make_spec(name, seed, effects=None, scheme=None, n_runs=None, crlf_bom=False, overrides=None):
    rng = np.random.default_rng(seed)
    ov = overrides or {}
    diameter = float(ov.get("diameter_mm", rng.choice([32.0, 40.0, 40.0, 50.0])))
    lead = float(ov.get("lead_mm", rng.choice([10.0, 10.0, 16.0, 20.0])))
    length = float(ov.get("length_mm", rng.choice([800.0, 900.0, 1000.0, 1100.0, 1200.0])))
    fixed_end = float(ov.get("fixed_end_mm", -round(rng.uniform(35, 80))))
    nut_len = float(round(2.0 * diameter + rng.uniform(0, 20)))
    margin_free = 0.5 * nut_len + 60.0
    travel_hi = float(np.floor((fixed_end + length - margin_free) / 50.0) * 50.0)
    travel = [0.0, travel_hi]
    sch = SCHEMES[scheme if scheme is not None else int(rng.integers(len(SCHEMES)))]
    two_bearings = bool(ov.get("two_bearings", rng.random() < 0.7))
    with_motor = bool(ov.get("motor_channel", rng.random() < 0.4))

    channels = [{"kind": "nut", "id": sch["nut"][0], "quantity": "temperature", "role": "nut",
                 "location": sch["nut"][1]},
                {"kind": "bfix", "id": sch["bfix"][0], "quantity": "temperature", "role": "bearing",
                 "position_mm": round(fixed_end + rng.uniform(15, 30), 1), "location": sch["bfix"][1]}]
    if two_bearings:
        channels.append({"kind": "bfree", "id": sch["bfree"][0], "quantity": "temperature", "role": "bearing",
                         "position_mm": round(fixed_end + length - rng.uniform(12, 25), 1),
                         "location": sch["bfree"][1]})
    channels += [{"kind": "amb", "id": sch["amb"][0], "quantity": "temperature", "role": "ambient",
                  "location": sch["amb"][1]},
                 {"kind": "air", "id": sch["air"][0], "quantity": "temperature", "role": "air",
                  "location": sch["air"][1]},
                 {"kind": "struct", "id": sch["struct"][0], "quantity": "temperature", "role": "structure",
                  "location": sch["struct"][1]}]
    if with_motor:
        channels.append({"kind": "motor", "id": sch["motor"][0], "quantity": "temperature", "role": "motor",
                         "location": sch["motor"][1]})
    order = rng.permutation(len(channels)) if rng.random() < 0.4 else np.arange(len(channels))
    channels = [channels[i] for i in order]

    # friction coefficients scaled so that powers are a few W at typical speeds
    c_nut = float(ov.get("c_nut", rng.uniform(0.035, 0.06) * (diameter / 40.0) ** 1.5 * (lead / 10.0) ** 0.5))
    c_b = float(ov.get("c_b", rng.uniform(0.010, 0.020) * (diameter / 40.0)))
    h0 = float(ov.get("h0", rng.uniform(9.0, 14.0)))

    n_runs = n_runs or int(rng.choice([4, 5, 5]))
    feeds = list(rng.permutation([3000, 4500, 6000, 8000, 10000, 12000])[:n_runs])
    if max(feeds) < 10000:
        feeds[0] = 12000
    if min(feeds) > 4500:
        feeds[-1] = 3000
    run_prefix = rng.choice(["S", "MS", "R", "run"])
    runs = []
    for i, f in enumerate(feeds):
        span = rng.uniform(0.25, 0.7) * travel_hi
        lo = rng.uniform(0.05 * travel_hi, travel_hi - span - 0.05 * travel_hi)
        lo = float(round(lo / 5) * 5)
        hi = float(round((lo + span) / 5) * 5)
        runs.append({
            "id": f"{run_prefix}{i + 1}",
            "feed_mm_min": float(f),
            "range_mm": [lo, hi],
            "warmup_s": float(rng.choice([90, 100, 105, 120]) * 60),
            "cooldown_s": 3600.0,
            "interval_s": float(rng.choice([10, 12, 15]) * 60),
            "meas_feed": float(rng.choice([2000, 3000, 4000])),
            "acc_mm_s2": float(rng.uniform(1000, 2000)),
            "dwell_s": float(rng.uniform(3, 5)),
            "overrun_mm": float(rng.choice([3, 5, 5, 8])),
            "amb_phase": float(rng.uniform(0, 2 * np.pi)),
            "amb_drift_K_h": float(rng.uniform(-0.12, 0.12)),
            "hvac_phase": float(rng.uniform(0, 2 * np.pi)),
            "seed": int(rng.integers(1 << 30)),
        })
    env = {
        "room_C": float(rng.uniform(19.5, 22.5)),
        "amb_amp_K": float(rng.uniform(0.2, 0.6)), "amb_period_h": float(rng.uniform(8, 24)),
        "amb_hvac_amp_K": float(rng.uniform(0.03, 0.12)), "amb_hvac_period_min": float(rng.uniform(20, 45)),
        "air_tau_s": float(rng.uniform(600, 1200)), "air_offset_K": float(rng.uniform(-0.2, 0.3)),
        "air_gain_K_W": float(rng.uniform(0.02, 0.05)), "air_heat_tau_s": float(rng.uniform(900, 1800)),
        "air_hvac_amp_K": float(rng.uniform(0.05, 0.2)), "air_hvac_period_min": float(rng.uniform(30, 70)),
        "struct_tau_s": float(rng.uniform(3600, 7200)), "struct_offset_K": float(rng.uniform(-0.4, 0.1)),
        "struct_gain_K_W": float(rng.uniform(0.04, 0.08)), "struct_heat_tau_s": float(rng.uniform(1800, 3600)),
        "motor_R_K_W": float(rng.uniform(0.6, 1.2)), "motor_tau_s": float(rng.uniform(900, 1500)),
    }
    env.update(ov.get("env", {}))
    spec = {
        "name": name, "seed": seed,
        "screw": {"length_mm": length, "diameter_mm": diameter, "lead_mm": lead, "fixed_end_mm": fixed_end,
                  "alpha_per_K": 11.5e-6, "density_kg_m3": 7850.0, "specific_heat_J_kgK": 460.0,
                  "conductivity_W_mK": 45.0},
        "nut_length_mm": nut_len,
        "travel_mm": travel,
        "targets": [float(x) for x in iso_targets(travel, int(rng.choice([11, 11, 12])), rng)],
        "bearing_region_mm": float(rng.uniform(25, 45)),
        "dead_path_mm": float(ov.get("dead_path_mm", rng.choice([100.0, 150.0, 250.0, 400.0]))),
        "environment_compensation": bool(ov.get("environment_compensation", True)),
        "physics": {"c_nut_W_s_rad": c_nut, "c_b_W_s_rad": c_b, "h0_W_m2K": h0},
        "drive": {"coulomb_Nm": float(rng.uniform(0.5, 1.1)), "viscous_Nms": float(rng.uniform(0.002, 0.006)),
                  "j_motor": float(rng.uniform(1e-3, 3e-3)), "table_kg": float(rng.uniform(150, 600)),
                  "motor_loss_W_Nm2": float(rng.uniform(2.0, 4.0))},
        "geometry": {"lead_error_um_m": float(rng.uniform(-15, 15)), "periodic_amp_um": float(rng.uniform(0.5, 2.0)),
                     "periodic_wavelength_mm": float(rng.uniform(120, 320)), "periodic_phase": float(rng.uniform(0, 6.28)),
                     "reversal_um": float(rng.uniform(1.5, 4.0)), "target_scatter_um": 0.3},
        "noise": {"temp_K": float(rng.uniform(0.01, 0.03)), "laser_um": float(rng.uniform(0.2, 0.4)),
                  "torque_Nm": float(rng.uniform(0.02, 0.08)), "missing_fraction": float(rng.uniform(0.0005, 0.003))},
        "sampling": {"period_s": float(rng.choice([5.0, 5.0, 7.5, 10.0])), "jitter_s": float(rng.uniform(0.1, 0.6))},
        "env": env,
        "channels": channels,
        "runs": runs,
        "effects": effects or {},
        "crlf_bom": crlf_bom,
    }
    # How the drive logs its torque: "instantaneous" samples (signed), or
    # "rms", the RMS since the previous sample that a drive's I2t channel gives.
    spec["torque_log"] = ov.get("torque_log", "instantaneous")
    return spec


def channel_id(spec, kind):
    for c in spec["channels"]:
        if c["kind"] == kind:
            return c["id"]
    raise KeyError(kind)


