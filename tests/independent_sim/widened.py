#!/usr/bin/python3
"""Write the widened hidden-effect suite (widened_suite.py).

    python3 widened.py --out DIR [--only NAME[,NAME...]] [--no-refit]
    python3 campaigns.py --suite widened --out DIR ...   (the same)

Same bundle and manifest format as campaigns.py.  The labels are fixed in
widened_suite.py; with the refit (default) every effect's contribution left
after a base-model refit is computed, and each label is checked against the
rule it rests on (a CHECK line on stderr and truth.label_check).
"""
import argparse
import json
import math
import os
import sys
import time

for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")   # one core

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from screwsim import first_order_lag  # noqa: E402  (re-runs with Debian's python3 if needed)
import numpy as np  # noqa: E402

from spec import make_spec, EDLEN_PPM_PER_K, DT  # noqa: E402
from campaign_sim import simulate_campaign, base_refit_residual, RunSim  # noqa: E402,F401
from bundle_writer import write_bundle  # noqa: E402
from campaigns import effect_cause_ids  # noqa: E402
from widened_suite import suite  # noqa: E402

THERMAL = ("forced_convection", "nut_heat_exponent", "motor_heat", "bearing_asym")
SENSOR = ("sensor_lag", "sensor_offset")
VISIBLE = 2.5      # an effect on positioning counts as visible at this x the laser noise
SENSOR_VISIBLE = 3.0


def rms(a):
    a = np.concatenate([np.ravel(x) for x in a]) if isinstance(a, (list, tuple)) else np.ravel(a)
    return float(np.sqrt(np.mean(a ** 2)))


def make_rig(entry):
    """Spec of an entry with its rig's changes applied."""
    rig = entry["rig"]
    spec = make_spec(entry["name"], entry["seed"], n_runs=rig.get("n_runs"), overrides=rig.get("overrides"))
    drop = set(rig.get("drop", ()))
    spec["channels"] = [c for c in spec["channels"] if c["kind"] not in drop]
    if "jitter_frac" in rig:
        spec["sampling"]["jitter_s"] = rig["jitter_frac"] * spec["sampling"]["period_s"]
    if rig.get("merged"):
        spec["sampling"] = {"period_s": 10.0, "jitter_s": 0.2, "axis_period_s": 2.0, "axis_jitter_s": 0.05}
    holes = []
    for i, frac, minutes, kinds in rig.get("holes", ()):
        r = spec["runs"][i]
        t0 = round(frac * (r["warmup_s"] + r["cooldown_s"]), 1)
        present = [k for k in kinds if any(c["kind"] == k for c in spec["channels"])]
        holes.append({"run": r["id"], "t0_s": t0, "t1_s": t0 + 60.0 * minutes, "kinds": present,
                      "channels": [c["id"] for c in spec["channels"] if c["kind"] in present]})
    spec["log"] = {"holes": holes}
    om_max = 2 * math.pi * max(r["feed_mm_min"] for r in spec["runs"]) / 60.0 / spec["screw"]["lead_mm"]
    if entry["effects_fn"]:
        spec["effects"] = entry["effects_fn"](spec, om_max)
    return spec


# ---------------------------------------------------------------------------
# what each effect leaves after the base model, and what candidates could take of it
# ---------------------------------------------------------------------------
def edlen_columns(spec, sim, air_at_readings):
    """Edlen term of a logged air signal (um per unit s) at every reading, per run."""
    cols = {}
    for r, d in sim.items():
        a = air_at_readings[r]
        cols[r] = EDLEN_PPM_PER_K * (a - a[0]) * (d["xr"] + spec["dead_path_mm"]) * 1000.0
    return cols


def logged_air(spec, sim):
    """The air sensor's noise-free reading (with its fault, if any) at the reading times."""
    return {r: np.interp(d["tr"], d["ts"], d["true"]["air"]) for r, d in sim.items()}


def frame_columns(spec, sim, taus=(0.0, 3600.0, 9000.0)):
    """Candidate frame-growth shapes: the structure's rise through a lag (per run, one column per tau)."""
    cols = {}
    for r, d in sim.items():
        rs = d["rs"]
        st = d["struct_b"]
        cols[r] = np.stack([rs.interp_steps(first_order_lag(st, DT, t), d["tr"]) - st[0] for t in taus], 1)
    return cols


def motor_columns(spec, base_sim, taus=(0.0, 1200.0, 3600.0, 7200.0)):
    """Candidate motor-heat shapes: thermal error of a unit k*torque^2 into the fixed end, per lag."""
    out = {r: [] for r in base_sim}
    for t in taus:
        sp = dict(spec, effects={"motor_heat": {"k_W_per_Nm2": 1.0, "tau_s": t}})
        s1 = simulate_campaign(sp)
        for r in base_sim:
            out[r].append(s1[r]["E"] - base_sim[r]["E"])
    return {r: np.stack(v, 1) for r, v in out.items()}


HEAT_CANDIDATES = ("motor_heat",)     # a heat input: its coefficient is >= 0


def best_with(spec, target, cands):
    """Base refit with each candidate's columns in turn (one column at a time): the best.
    Output candidates (refraction, frame growth) take either sign, heat inputs only >= 0."""
    best = None
    for name, cols in cands.items():
        m = next(iter(cols.values())).shape[1] if next(iter(cols.values())).ndim == 2 else 1
        for j in range(m):
            ex = {r: (c[:, j] if c.ndim == 2 else c) for r, c in cols.items()}
            res, par = base_refit_residual(spec, target, extra=ex, extra_nonneg=name in HEAT_CANDIDATES)
            if best is None or res < best[0]:
                best = (res, name, j)
    return best


def contributions(spec, sim, refit):
    eff = spec["effects"]
    laser, tn = spec["noise"]["laser_um"], spec["noise"]["temp_K"]
    c = {"_laser_noise_um": laser, "_temp_noise_K": tn}
    thermal = [k for k in eff if k in THERMAL]
    base_sim = sim     # output and sensor effects leave the screw's thermal error as it is
    if thermal:
        base_sim = simulate_campaign(dict(spec, effects={k: v for k, v in eff.items() if k not in THERMAL}))
    E_base = {r: base_sim[r]["E"] for r in sim}
    for k in eff:
        if k in THERMAL:
            c[k] = {"raw_rms_um": rms([sim[r]["E"] - E_base[r] for r in sim])}
        elif k not in SENSOR:
            c[k] = {"raw_rms_um": rms([sim[r]["contrib"][k] for r in sim])}
    # sensor faults, in the sensor's own reading (noise-free with minus without the fault)
    for k in SENSOR:
        if k not in eff:
            continue
        ch = eff[k]["channel"]
        kind = next(x["kind"] for x in spec["channels"] if x["id"] == ch)
        if k == "sensor_offset":
            size = abs(eff[k]["offset_K"])
            c[f"{k}:{ch}"] = {"rms_K": size, "x_temp_noise": size / tn}
        else:
            d = [sim[r]["true"][kind] - sim[r]["unlagged"][kind] for r in sim]
            c[f"{k}:{ch}"] = {"rms_K": rms(d), "peak_K": float(max(np.abs(x).max() for x in d)),
                              "x_temp_noise": rms(d) / tn}
    if not refit:
        return c
    if thermal:
        res, par = base_refit_residual(spec, {r: sim[r]["E"] for r in sim})
        for k in thermal:
            c[k].update(after_base_refit_rms_um=res, x_laser_noise=res / laser, base_refit=par)
        c["_base_refit_on_base_data_rms_um"] = base_refit_residual(spec, E_base, h_factors=(1.0,))[0]
    for k in eff:
        if k in THERMAL or k in SENSOR:
            continue
        res, par = base_refit_residual(spec, {r: E_base[r] + sim[r]["contrib"][k] for r in sim})
        c[k].update(after_base_refit_rms_um=res, x_laser_noise=res / laser, base_refit=par)
    # an air sensor's lag shows through the refraction candidate that reads it
    lag = eff.get("sensor_lag", {})
    air_ch = [x["id"] for x in spec["channels"] if x["kind"] == "air"]
    if "air_refraction" in eff and air_ch and lag.get("channel") == air_ch[0]:
        tgt = {r: E_base[r] + sim[r]["contrib"]["air_refraction"] for r in sim}
        res, par = base_refit_residual(spec, tgt, extra=edlen_columns(spec, sim, logged_air(spec, sim)))
        c[f"sensor_lag:{lag['channel']}"].update(
            after_base_and_refraction_on_logged_air_rms_um=res, x_laser_noise=res / laser, s_fitted=par["extra"])
    # structure no candidate's form was meant for: what the best single candidate leaves
    if any(k in eff for k in ("bearing_asym",)) or ("frame_growth" in eff and
                                                   not any(x["kind"] == "struct" for x in spec["channels"])):
        k = "bearing_asym" if "bearing_asym" in eff else "frame_growth"
        tgt = {r: sim[r]["E"] + sim[r]["contrib"].get("frame_growth", 0.0) for r in sim}
        cands = {"motor_heat": motor_columns(spec, base_sim)}
        if any(x["kind"] == "air" for x in spec["channels"]):
            cands["air_refraction"] = edlen_columns(spec, sim, logged_air(spec, sim))
        if any(x["kind"] == "struct" for x in spec["channels"]):
            cands["frame_growth"] = frame_columns(spec, sim)
        res, name, j = best_with(spec, tgt, cands)
        before = c[k]["after_base_refit_rms_um"]
        c[k].update(after_best_candidate_rms_um=res, best_candidate=name, best_candidate_shape=j,
                    best_candidate_gain=1.0 - res / before if before > 0 else 0.0)
        if k == "bearing_asym":   # the modelled sensors under the refitted base parameters
            c[k]["sensor_residual_under_refit"] = sensor_residuals(spec, sim, c[k]["base_refit"])
    return c


def sensor_residuals(spec, sim, par):
    """RMS (K, and x the sensor noise) of base model (refitted parameters) minus truth at
    the sensors the base model predicts (nut, bearings)."""
    phys = {"c_nut_W_s_rad": par["c_nut"], "c_b_W_s_rad": par["c_b"], "h0_W_m2K": par["h"]}
    s2 = simulate_campaign(dict(spec, effects={}, physics=phys))
    out = {}
    for ch in spec["channels"]:
        if ch["kind"] in ("nut", "bfix", "bfree"):
            v = rms([s2[r]["true"][ch["kind"]] - sim[r]["true"][ch["kind"]] for r in sim])
            out[ch["id"]] = {"rms_K": v, "x_temp_noise": v / spec["noise"]["temp_K"]}
    return out


def check_label(expected, c, spec):
    """The rule each label rests on, tested on the numbers (True, or the reason it fails)."""
    laser = spec["noise"]["laser_um"]
    msgs = []
    for k, v in c.items():
        if k.startswith("_"):
            continue
        if "x_laser_noise" in v and k in spec["effects"] and k != "bearing_asym":
            if v["x_laser_noise"] < VISIBLE and (k in expected or k == "frame_growth"):
                msgs.append(f"{k}: only {v['x_laser_noise']:.1f}x the laser noise after the base refit")
        if k.startswith("sensor_") and k in expected:
            if "x_laser_noise" in v and v["x_laser_noise"] < VISIBLE:   # seen only through positioning
                msgs.append(f"{k}: leaves only {v['x_laser_noise']:.1f}x the laser noise")
            elif v.get("x_temp_noise", 99) < SENSOR_VISIBLE:
                msgs.append(f"{k}: only {v['x_temp_noise']:.1f}x the sensor noise")
    if "bearing_asym" in c and "after_base_refit_rms_um" in c["bearing_asym"]:
        x = c["bearing_asym"]["after_base_refit_rms_um"] / laser
        if expected == [] and x > 1.0:
            msgs.append(f"bearing_asym labelled none but leaves {x:.1f}x the laser noise")
        if expected == ["unexplained"] and x < VISIBLE:
            msgs.append(f"bearing_asym labelled unexplained but leaves only {x:.1f}x the laser noise")
    for k in ("bearing_asym", "frame_growth"):
        v = c.get(k, {})
        if expected == ["unexplained"] and "best_candidate_gain" in v and v["best_candidate_gain"] > 0.5:
            msgs.append(f"{k}: candidate {v['best_candidate']} explains {v['best_candidate_gain']:.0%}")
    thermal_or_out = [k for k in expected if k in c and "after_base_refit_rms_um" in c[k]]
    if len(thermal_or_out) == 2:
        a, b = (c[k]["after_base_refit_rms_um"] for k in thermal_or_out)
        if a < b:
            msgs.append(f"order: {thermal_or_out} but after-refit {a:.2f} < {b:.2f} um")
    return msgs or True


def build(entry, outroot, refit=True):
    t0 = time.time()
    spec = make_rig(entry)
    sim = simulate_campaign(spec, keep_fields=False)
    write_bundle(spec, sim, os.path.join(outroot, entry["name"]))
    contrib = contributions(spec, sim, refit)
    eff = spec["effects"]
    if entry["expected"] is not None:
        expected = list(entry["expected"])
    else:   # effects each named by its cause id (one positioning effect, then sensor effects)
        ids = effect_cause_ids(eff)
        expected = [i for i in ids if not i.startswith("sensor_")] + [i for i in ids if i.startswith("sensor_")]
    truth = {
        "seed": spec["seed"], "screw": spec["screw"], "nut_length_mm": spec["nut_length_mm"],
        "travel_mm": spec["travel_mm"], "targets_mm": spec["targets"], "physics": spec["physics"],
        "bearing_heat": "c_b*|omega| into each end region (fixed and free), "
                        f"{spec['bearing_region_mm']:.0f} mm long, unless effects.bearing_asym says otherwise",
        "effects": eff, "effect_contributions": contrib,
        "channels": {c["id"]: c["role"] for c in spec["channels"]},
        "dropped_channel_kinds": list(entry["rig"].get("drop", ())),
        "dead_path_mm": spec["dead_path_mm"], "environment_compensation": spec["environment_compensation"],
        "noise": spec["noise"], "sampling": spec["sampling"], "log_holes": spec["log"]["holes"],
        "geometry": spec["geometry"], "drive": spec["drive"], "environment": spec["env"],
        "runs": [{k: r[k] for k in ("id", "feed_mm_min", "range_mm", "warmup_s", "cooldown_s", "interval_s",
                                      "meas_feed", "acc_mm_s2", "dwell_s", "overrun_mm")} for r in spec["runs"]],
        "run_summary": {r: sim[r]["summary"] for r in sim},
        "thermal_error_rms_um": rms([sim[r]["E"] for r in sim]),
    }
    if refit:
        truth["label_check"] = check_label(expected, contrib, spec)
    truth["generation_s"] = round(time.time() - t0, 2)
    return {"bundle": entry["name"], "expected": expected, "truth": truth, "description": entry["description"]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--only", default="", help="comma-separated bundle names")
    ap.add_argument("--no-refit", action="store_true", help="skip the base refits (labels are the same)")
    ap.add_argument("--verbose", action="store_true", help="a line per bundle written, on stderr")
    a = ap.parse_args(argv)
    entries = suite()
    if a.only:
        names = set(a.only.split(","))
        entries = [e for e in entries if e["name"] in names]
    os.makedirs(a.out, exist_ok=True)
    t0 = time.time()
    manifest = []
    for e in entries:
        m = build(e, a.out, refit=not a.no_refit)
        manifest.append(m)
        tr = m["truth"]
        line = f"{e['name']:42s} expected={m['expected']}  ({tr['generation_s']:.1f} s)"
        for k, v in tr["effect_contributions"].items():
            if not k.startswith("_"):
                x = v.get("x_laser_noise", v.get("x_temp_noise"))
                line += f"  {k}: {x:.1f}x" if x is not None else f"  {k}: raw {v['raw_rms_um']:.2f} um"
        if a.verbose:
            print(line, file=sys.stderr)
        if tr.get("label_check", True) is not True:
            print(f"CHECK {e['name']}: {tr['label_check']}", file=sys.stderr)
    with open(os.path.join(a.out, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1)
    if a.verbose:
        print(f"wrote {len(manifest)} bundles to {a.out} in {time.time() - t0:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
