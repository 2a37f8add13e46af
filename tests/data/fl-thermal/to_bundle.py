#!/usr/bin/python3
"""Write FL_THERMAL's first 32 h (data.csv beside this script) as a DriftLab
campaign bundle in DIR: one spindle run per 8 h block of one constant speed.

    python3 to_bundle.py DIR
"""
import csv
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SPEEDS_RPM = [1250, 2500, 3750, 5000]
BLOCK_S = 8 * 3600


def main(out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(HERE, "data.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    channels = [{"id": "t%d" % i, "quantity": "temperature", "role": "other",
                 "location": "not documented upstream"} for i in range(1, 17)]
    channels.append({"id": "spindle_rpm", "quantity": "speed", "role": "spindle"})
    channels += [{"id": "ch%d_um" % i, "quantity": "displacement", "role": "drift",
                  "location": "cutter axis displacement (not documented upstream)"}
                 for i in range(1, 6)]
    runs = [{"id": "R%d" % s, "kind": "spindle",
             "description": "%d rpm for 4 h, then 4 h stopped" % s} for s in SPEEDS_RPM]
    campaign = {"format": "driftlab.campaign/1",
                "name": "FL_THERMAL spindle drift, first 32 h",
                "machine": {"name": "FL_THERMAL machining centre", "axis": "Z",
                            "controller": "generic"},
                "channels": channels, "runs": runs}
    with open(os.path.join(out, "campaign.json"), "w") as f:
        json.dump(campaign, f, indent=1)
    columns = [c["id"] for c in channels]
    with open(os.path.join(out, "samples.csv"), "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["run", "time_s"] + columns)
        for r in rows:
            t = float(r["time_s"])
            block = int(t // BLOCK_S)
            if block < len(runs):
                writer.writerow([runs[block]["id"], "%g" % (t - block * BLOCK_S)] +
                                [r[c] for c in columns])


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
