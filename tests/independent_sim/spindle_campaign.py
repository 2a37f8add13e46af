#!/usr/bin/python3
"""ISO 230-3 spindle campaigns from a thermal network DriftLab did not write.

Written from docs/bundles.md (the bundle format and the channel roles) and textbook
lumped-capacity heat transfer, not from core/rig: ten nodes (bearings, motor,
rotor and shaft, housing, headstock, column skins and core) joined by thermal
conductances, integrated with scipy's LSODA block by block. Sixteen
thermometers, as on the instrumented spindles of the literature: some on a
node, some on a surface between a node and the room, some between two nodes;
none on the shaft or the column core, so the drift lags every sensor. Five
probes; temperatures logged every 10 s, probes every 5 s (the temperature
cells of the rows in between are empty, as a logger merging two devices
writes them). Beside each bundle, truth_drift.csv holds the probes' drift
before their noise. Usage: spindle_campaign.py --out DIR [--seeds 1,2].
"""
import argparse
import json
import math
import os

import screwsim  # noqa: F401  (re-runs with Debian's python3 where numpy or scipy is missing)
import numpy as np
from scipy.integrate import solve_ivp

# Nodes: heat capacity (J/K), conductance to the room (W/K).
NODES = [
    ("bearing_front", 2500, 0.5),
    ("bearing_rear", 2000, 0.4),
    ("stator", 7000, 1.0),
    ("shaft", 9000, 1.0),
    ("housing_front", 16000, 4.0),
    ("housing_rear", 16000, 4.0),
    ("headstock", 70000, 12.0),
    ("column_front", 160000, 25.0),
    ("column_rear", 200000, 25.0),
    ("column_core", 650000, 2.0),
]
IDX = {name: i for i, (name, _, _) in enumerate(NODES)}
# Conductances between nodes (W/K).
LINKS = [
    ("bearing_front", "shaft", 3.0), ("bearing_front", "housing_front", 8.0),
    ("bearing_rear", "shaft", 2.0), ("bearing_rear", "housing_rear", 5.0),
    ("stator", "housing_rear", 10.0), ("stator", "shaft", 4.0),
    ("housing_front", "housing_rear", 6.0), ("housing_front", "headstock", 10.0),
    ("housing_rear", "headstock", 10.0), ("headstock", "column_front", 15.0),
    ("headstock", "column_rear", 5.0), ("column_front", "column_core", 20.0),
    ("column_rear", "column_core", 20.0), ("column_front", "column_rear", 5.0),
]

# Thermometers: (id, role, location, {node: weight}); weights short of 1 are the room's.
SENSORS = [
    ("TC01", "spindle", "front bearing outer ring", {"bearing_front": 1.0}),
    ("TC02", "spindle", "rear bearing outer ring", {"bearing_rear": 1.0}),
    ("TC03", "motor", "motor stator", {"stator": 1.0}),
    ("TC04", "spindle", "housing, front left", {"housing_front": 0.85}),
    ("TC05", "spindle", "housing, front right", {"housing_front": 0.9}),
    ("TC06", "spindle", "housing, rear", {"housing_rear": 1.0}),
    ("TC07", "other", "housing, rear top", {"housing_rear": 0.8}),
    ("TC08", "structure", "headstock, left", {"headstock": 1.0}),
    ("TC09", "structure", "headstock, right", {"headstock": 0.9}),
    ("TC10", "structure", "column front, top", {"column_front": 1.0}),
    ("TC11", "structure", "column front, bottom", {"column_front": 0.7, "column_core": 0.3}),
    ("TC12", "structure", "column rear, top", {"column_rear": 1.0}),
    ("TC13", "structure", "column rear, bottom", {"column_rear": 0.7, "column_core": 0.3}),
    ("TC14", "other", "coolant return", {"stator": 0.5, "housing_rear": 0.5}),
    ("TC15", "ambient", "room, 1.5 m from the column", {}),
    ("TC16", "structure", "machine base", {"column_core": 0.5}),
]

# Probes (µm per K of node rise): shaft and housing growth in z, column
# bending (front against rear skin) in y and in the tilt about x.
PROBES = [
    ("X1", "drift_x", {"housing_front": 0.25, "housing_rear": -0.25, "shaft": 0.15}),
    ("Y1", "drift_y", {"column_front": -2.5, "column_rear": 2.5, "column_core": -0.8, "headstock": 0.3}),
    ("Z1", "drift_z", {"shaft": -1.5, "housing_front": -1.0, "housing_rear": -0.5,
                       "headstock": -1.5, "column_core": -2.0}),
    ("Y2", "tilt_a", {"column_front": -0.6, "column_rear": 0.6, "housing_front": 0.2}),
    ("X2", "tilt_b", {"housing_front": 0.1, "housing_rear": -0.1, "shaft": 0.05}),
]

HOUR = 3600.0


def heat_W(speed_rpm):
    """Bearing friction grows as n^1.25, motor and rotor losses as n^1.8 and n^2."""
    n = abs(speed_rpm) / 10000.0
    q = np.zeros(len(NODES))
    q[IDX["bearing_front"]] = 120 * n ** 1.25
    q[IDX["bearing_rear"]] = 50 * n ** 1.25
    q[IDX["stator"]] = 150 * n ** 1.8 + (10 if n > 0 else 0)
    q[IDX["shaft"]] = 30 * n ** 2
    return q


def system():
    cap = np.array([c for _, c, _ in NODES])
    g = np.diag([-room for _, _, room in NODES]).astype(float)
    for a, b, k in LINKS:
        i, j = IDX[a], IDX[b]
        g[i, i] -= k
        g[j, j] -= k
        g[i, j] += k
        g[j, i] += k
    room = np.array([r for _, _, r in NODES])
    return cap, g, room


def programmes(rng):
    """Six speed programmes (rpm, seconds): constant, staircase, spectra, steps."""
    def spectrum(total_s):
        blocks, t = [], 0.0
        while t < total_s:
            d = float(rng.uniform(5, 25)) * 60
            blocks.append((float(rng.choice([0, 2000, 4000, 6000, 8000, 10000])), d))
            t += d
        return blocks
    stop = [(0.0, 2 * HOUR)]
    return [
        [(6000.0, 4 * HOUR)] + stop,
        [(2000.0, HOUR), (4000.0, HOUR), (6000.0, HOUR), (8000.0, HOUR)] + stop,
        spectrum(4 * HOUR) + stop,
        [(8000.0, 2 * HOUR), (0.0, HOUR), (4000.0, 2 * HOUR)] + stop,
        spectrum(4 * HOUR) + stop,
        [(3000.0, 3 * HOUR), (9000.0, HOUR)] + stop,
    ]


def simulate_run(blocks, rng, dt_s=5.0):
    cap, g, room_g = system()
    phase = rng.uniform(0, 2 * math.pi)
    walk = rng.normal(0, 0.03, 64).cumsum()

    def room_C(t):
        return 20.0 + 0.6 * math.sin(2 * math.pi * t / (24 * HOUR) + phase) + np.interp(t, np.arange(64) * 600, walk)

    total = sum(d for _, d in blocks)
    ts = np.arange(0, total + 1e-9, dt_s)
    temps = np.empty((len(ts), len(NODES)))
    speed = np.empty(len(ts))
    y = np.full(len(NODES), room_C(0.0))
    start = 0.0
    for rpm, d in blocks:
        end = start + d
        q = heat_W(rpm)
        f = lambda t, T: (g @ T + room_g * room_C(t) + q) / cap  # noqa: E731
        at = (ts >= start - 1e-9) & (ts <= end + 1e-9)
        sol = solve_ivp(f, (start, end), y, method="LSODA", t_eval=ts[at], rtol=1e-8, atol=1e-9)
        temps[at] = sol.y.T
        speed[at] = rpm
        y = sol.y[:, -1]
        start = end
    speed[-1] = 0.0
    rooms = np.array([room_C(t) for t in ts])
    return ts, temps, rooms, speed


def lag(x, tau_s, dt_s):
    a = math.exp(-dt_s / tau_s)
    out = np.empty_like(x)
    out[0] = x[0]
    for i in range(1, len(x)):
        out[i] = a * out[i - 1] + (1 - a) * x[i]
    return out


def write(outdir, seed):
    rng = np.random.default_rng(seed)
    os.makedirs(outdir, exist_ok=True)
    channels = [{"id": s[0], "quantity": "temperature", "role": s[1], "location": s[2]} for s in SENSORS]
    channels.append({"id": "n_spindle", "quantity": "speed", "role": "spindle", "location": "spindle drive"})
    channels += [{"id": p[0], "quantity": "displacement", "role": p[1], "location": "test mandrel probe"}
                 for p in PROBES]
    runs, rows, truth = [], [], []
    for r, blocks in enumerate(programmes(rng)):
        run_id = f"P{r + 1}"
        runs.append({"id": run_id, "kind": "spindle",
                     "description": "speed programme " + ", ".join(f"{s:.0f} rpm {d / 60:.0f} min" for s, d in blocks)})
        ts, temps, rooms, speed = simulate_run(blocks, rng)
        rise = temps - temps[0]
        readings = []
        for _, _, _, weights in SENSORS:
            true = rooms * (1 - sum(weights.values())) + sum(w * temps[:, IDX[n]] for n, w in weights.items())
            read = lag(true, 30.0, 5.0) + rng.normal(0, 0.02, len(ts))
            readings.append(np.round(read, 2))
        true_drifts = [sum(w * rise[:, IDX[n]] for n, w in weights.items()) for _, _, weights in PROBES]
        drifts = [np.round(d + rng.normal(0, 0.15, len(ts)), 2) for d in true_drifts]
        truth += [",".join([run_id, f"{t:.1f}"] + [f"{d[i]:.5f}" for d in true_drifts])
                  for i, t in enumerate(ts)]
        for i, t in enumerate(ts):
            logged = i % 2 == 0  # the thermometers every 10 s, the probes every 5 s
            row = [run_id, f"{t:.1f}"] + [f"{v[i]:.2f}" if logged else "" for v in readings]
            row += [f"{speed[i]:.0f}"] + [f"{d[i]:.2f}" for d in drifts]
            rows.append(",".join(row))
    campaign = {"format": "driftlab.campaign/1", "name": f"Independent spindle campaign (seed {seed})",
                "machine": {"name": "IndepSim-HMC", "axis": "Z", "controller": "generic"},
                "channels": channels, "runs": runs}
    with open(os.path.join(outdir, "campaign.json"), "w") as f:
        json.dump(campaign, f, indent=2)
    with open(os.path.join(outdir, "samples.csv"), "w") as f:
        f.write(",".join(["run", "time_s"] + [c["id"] for c in channels]) + "\n")
        f.write("\n".join(rows) + "\n")
    # Not part of the bundle: the probes' drift before their noise, from each
    # run's start (µm), for the tests to know what a perfect model would score.
    with open(os.path.join(outdir, "truth_drift.csv"), "w") as f:
        f.write(",".join(["run", "time_s"] + [p[0] for p in PROBES]) + "\n")
        f.write("\n".join(truth) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seeds", default="1", help="comma-separated; one campaign per seed, in OUT/seed-N")
    args = ap.parse_args()
    for seed in (int(s) for s in args.seeds.split(",")):
        write(os.path.join(args.out, f"seed-{seed}"), seed)


if __name__ == "__main__":
    main()
