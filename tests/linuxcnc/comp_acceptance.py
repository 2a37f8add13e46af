#!/usr/bin/python3
"""Acceptance test of DriftLab's LinuxCNC COMP_FILE export on a real LinuxCNC.

1. `driftlab-cli simulate` makes a campaign (run S1: an axis with a cold
   geometric error, backlash and thermal drift, read by a simulated laser).
2. `driftlab-cli compensate --format linuxcnc|linuxcnc-type1` exports S1's
   table; `driftlab-cli iso230-2 --json` gives the ISO 230-2 mean deviations
   it was made from.
3. A simulated one-axis LinuxCNC 2.9 loads the table ([JOINT_0]COMP_FILE,
   COMP_FILE_TYPE), homes, and goes to positions on and between table points,
   each approached from below and from above.
4. At each, the correction LinuxCNC applies, joint.0.motor-pos-cmd -
   joint.0.pos-cmd (less motor-offset, 0 here), must equal minus the deviation
   DriftLab measured, interpolated linearly between targets, within 1 um:
   bidirectional table: -x_up(x) approaching from below, -x_down(x) from above;
   unidirectional: -(x_mean(x) +/- B_mean/2), the backlash B_mean being folded
   into the two columns (docs/compensation.md).

Usage: comp_acceptance.py --cli DRIFTLAB_CLI --format linuxcnc|linuxcnc-type1
       [--bidirectional] [--spacing MM]
Exit 0 pass, 1 fail, 77 LinuxCNC not installed.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lcnc_sim  # noqa: E402

TOLERANCE_UM = 1.0
APPROACH_MM = 5.0


def cli(binary, *args):
    done = subprocess.run([binary, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit("driftlab-cli %s failed (%d): %s"
                         % (" ".join(args), done.returncode, done.stderr.strip()))
    return done.stdout


def interpolated(points, x):
    """Linear between (x, y) points, as both DriftLab and LinuxCNC do."""
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if x <= x1 + 1e-9:
            return y0 + (x - x0) / (x1 - x0) * (y1 - y0)
    raise ValueError("%.4f mm is beyond the measured targets" % x)


def expected_trims(iso, bidirectional):
    """Per direction, the correction in um at each target: what LinuxCNC
    should add to the command there."""
    targets = iso["targets"]
    if bidirectional:
        up = [(t["target_mm"], -t["mean_up"]) for t in targets]
        down = [(t["target_mm"], -t["mean_down"]) for t in targets]
    else:
        half_b = iso["B_mean"] / 2
        up = [(t["target_mm"], -(t["mean"] + half_b)) for t in targets]
        down = [(t["target_mm"], -(t["mean"] - half_b)) for t in targets]
    return {"+": up, "-": down}


def test_positions(targets_mm):
    """Table points and points between them, first to last target."""
    t = targets_mm
    between = lambda i, f: round(t[i] + f * (t[i + 1] - t[i]), 4)  # noqa: E731
    chosen = [t[0], between(0, 0.37), t[1], between(2, 0.5), t[len(t) // 2],
              between(len(t) // 2, 0.8), between(len(t) - 2, 0.25), t[-1]]
    return sorted(set(chosen))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--format", required=True, choices=("linuxcnc", "linuxcnc-type1"))
    parser.add_argument("--bidirectional", action="store_true")
    parser.add_argument("--spacing")
    args = parser.parse_args()
    lcnc_sim.skip_unless_available()

    with tempfile.TemporaryDirectory(prefix="driftlab-comp-") as work:
        campaign = os.path.join(work, "campaign")
        cli(args.cli, "simulate", "--out", campaign, "--runs", "S1", "--seed", "1")
        table = os.path.join(work, "x.comp")
        export = ["compensate", campaign, "--run", "S1", "--format", args.format,
                  "--out", table]
        if args.bidirectional:
            export.append("--bidirectional")
        if args.spacing:
            export += ["--spacing", args.spacing]
        cli(args.cli, *export)
        iso = json.loads(cli(args.cli, "iso230-2", campaign, "--run", "S1", "--json"))
        with open(table) as f:
            rows = f.read().splitlines()
        comp_type = 0 if args.format == "linuxcnc" else 1
        print("table %s (COMP_FILE_TYPE %d, %s, %d rows): first %s, last %s"
              % (args.format, comp_type,
                 "bidirectional" if args.bidirectional else "unidirectional",
                 len(rows), rows[0], rows[-1]))

        expected = expected_trims(iso, args.bidirectional)
        positions = test_positions([t["target_mm"] for t in iso["targets"]])
        code, output, result, seconds = lcnc_sim.run(
            "comp_display.py", {"positions_mm": positions, "approach_mm": APPROACH_MM},
            joint_extra="COMP_FILE = %s\nCOMP_FILE_TYPE = %d" % (table, comp_type))
    print("LinuxCNC run: %.1f s, exit %d" % (seconds, code))
    if code != 0 or result is None:
        print(output)
        print("FAIL: LinuxCNC run did not complete")
        return 1
    return judge(result["readings"], expected, 2 * len(positions))


def judge(readings, expected, count):
    print("%-12s %-4s %-14s %-14s %-12s" % ("position_mm", "dir", "correction_um",
                                            "expected_um", "error_um"))
    failures, largest_um = 0, 0.0
    for r in readings:
        x, direction = r["position_mm"], r["direction"]
        if abs(r["joint.0.pos-cmd"] - x) > 1e-9:
            print("FAIL: joint at %.6f mm, not %.4f" % (r["joint.0.pos-cmd"], x))
            failures += 1
        correction_um = (r["joint.0.motor-pos-cmd"] - r["joint.0.pos-cmd"]
                         - r["joint.0.motor-offset"]) * 1000
        want_um = interpolated(expected[direction], x)
        error_um = correction_um - want_um
        largest_um = max(largest_um, abs(want_um))
        bad = abs(error_um) > TOLERANCE_UM
        failures += bad
        print("%-12.4f %-4s %-14.3f %-14.3f %-12.3f%s" % (x, direction, correction_um,
                                                           want_um, error_um,
                                                           "  FAIL" if bad else ""))
    # A table LinuxCNC ignored would give corrections of 0: only a table with
    # corrections well above the tolerance proves it was applied.
    if len(readings) != count:
        print("FAIL: %d readings, not %d" % (len(readings), count))
        failures += 1
    if largest_um < 5 * TOLERANCE_UM:
        print("FAIL: the largest expected correction is %.3f um: too small to tell "
              "an applied table from none" % largest_um)
        failures += 1
    print("%d readings, %d beyond %.1f um or off position" % (len(readings), failures,
                                                            TOLERANCE_UM))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(lcnc_sim.quiet_unless_failed(main))
