"""A simulated campaign written as a DriftLab bundle (docs/bundles.md, "The format")."""
import json
import math
import os

import numpy as np

from screwsim import Screw, FVModel, first_order_lag  # noqa: F401
from motion import moving_run, iso_targets, Drive, nut_heat_per_step  # noqa: F401

from spec import *  # noqa: F401,F403

# ---------------------------------------------------------------------------
# writing
# ---------------------------------------------------------------------------
def fmt(v, nd):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return ""
    s = f"{v:.{nd}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def log_blanks(spec, run_id, ts, kinds, has_temp=None):
    """Empty temperature cells of a logger: holes (spec["log"]["holes"]: every row in
    [t0_s, t1_s) of a run empty in the channels of `kinds`, as when a module does not
    answer) and the axis-only rows of a merged log (has_temp False)."""
    blank = np.zeros((len(ts), len(kinds)), bool)
    for hole in spec.get("log", {}).get("holes", []):
        if hole["run"] != run_id:
            continue
        rows = (ts >= hole["t0_s"]) & (ts < hole["t1_s"])
        for j, k in enumerate(kinds):
            if k in hole["kinds"]:
                blank[rows, j] = True
    if has_temp is not None:
        blank[~has_temp, :] = True
    return blank


def write_bundle(spec, sim, outdir):
    os.makedirs(outdir, exist_ok=True)
    sc = spec["screw"]
    camp = {
        "format": "driftlab.campaign/1",
        "name": f"{spec['name']} (independent simulator)",
        "machine": {"name": spec.get("machine", "IndepSim-VMC"), "axis": "X", "controller": "generic-modbus"},
        "screw": {"length_mm": sc["length_mm"], "diameter_mm": sc["diameter_mm"], "lead_mm": sc["lead_mm"],
                  "fixed_end_mm": sc["fixed_end_mm"], "mounting": "fixed-free", "alpha_per_K": sc["alpha_per_K"],
                  "density_kg_m3": sc["density_kg_m3"], "specific_heat_J_kgK": sc["specific_heat_J_kgK"],
                  "conductivity_W_mK": sc["conductivity_W_mK"]},
        "nut_length_mm": spec["nut_length_mm"],
        "travel_mm": spec["travel_mm"],
        "interferometer": {"dead_path_mm": spec["dead_path_mm"],
                           "environment_compensation": spec["environment_compensation"]},
        "channels": [{k: v for k, v in c.items() if k != "kind"} for c in spec["channels"]],
        "runs": [{"id": r["id"], "kind": "moving", "feed_mm_min": r["feed_mm_min"], "range_mm": r["range_mm"],
                  "description": (f"warm-up {r['feed_mm_min']:.0f} mm/min over {r['range_mm'][0]:.0f}-"
                                  f"{r['range_mm'][1]:.0f} mm for {r['warmup_s'] / 60:.0f} min, measurement cycle "
                                  f"every {r['interval_s'] / 60:.0f} min, then {r['cooldown_s'] / 60:.0f} min cool-down")}
                 for r in spec["runs"]],
    }
    with open(os.path.join(outdir, "campaign.json"), "w") as f:
        json.dump(camp, f, indent=2)
    nl = "\r\n" if spec.get("crlf_bom") else "\n"
    bom = "\ufeff" if spec.get("crlf_bom") else ""
    noise = spec["noise"]

    # samples.csv
    ids = [c["id"] for c in spec["channels"]]
    kinds = [c["kind"] for c in spec["channels"]]
    lines = [",".join(["run", "time_s"] + ids + ["position_mm", "feed_mm_min", "torque_Nm"])]
    for run in spec["runs"]:
        d = sim[run["id"]]
        rng = np.random.default_rng(run["seed"] + 2)
        ts = d["ts"]
        miss = rng.random((len(ts), len(ids))) < noise["missing_fraction"]
        miss[:3] = False
        miss |= log_blanks(spec, run["id"], ts, kinds, d.get("has_temp"))
        has_axis = d.get("has_axis")
        cols = [np.round(d["meas"][k], 3) for k in kinds]
        for i in range(len(ts)):
            row = [run["id"], fmt(ts[i], 2)]
            row += ["" if miss[i, j] else fmt(cols[j][i], 3) for j in range(len(ids))]
            if has_axis is None or has_axis[i]:
                row += [fmt(d["pos_s"][i], 3), fmt(d["vel_s"][i] * 60.0, 1), fmt(d["torque_s"][i], 3)]
            else:
                row += ["", "", ""]
            lines.append(",".join(row))
    with open(os.path.join(outdir, "samples.csv"), "w", newline="") as f:
        f.write(bom + nl.join(lines) + nl)

    # motion.csv
    lines = ["run,start_s,end_s,from_mm,to_mm,feed_mm_min"]
    for run in spec["runs"]:
        for t0, t1, x0, x1, feed in sim[run["id"]]["rs"].prog.motion_rows():
            lines.append(f"{run['id']},{t0:.3f},{t1:.3f},{fmt(x0, 4)},{fmt(x1, 4)},{fmt(feed, 1)}")
    with open(os.path.join(outdir, "motion.csv"), "w", newline="") as f:
        f.write(bom + nl.join(lines) + nl)

    # positioning.csv
    lines = ["run,time_s,cycle,target_mm,direction,deviation_um"]
    for run in spec["runs"]:
        d = sim[run["id"]]
        for (t, cyc, tg, di), dv in zip(d["readings"], d["dev"]):
            lines.append(f"{run['id']},{t:.2f},{cyc},{fmt(tg, 3)},{di},{dv:.3f}")
    with open(os.path.join(outdir, "positioning.csv"), "w", newline="") as f:
        f.write(bom + nl.join(lines) + nl)


