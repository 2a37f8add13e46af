#!/usr/bin/python3
"""Acceptance test of DriftLab's LinuxCNC COMP_FILE export on a real LinuxCNC.

1. `driftlab-cli simulate` makes a campaign (run S1: an axis with a cold
   geometric error, backlash and thermal drift, read by a simulated laser).
2. `driftlab-cli compensate --format linuxcnc|linuxcnc-type1 [--sign S]
   [--bidirectional]` exports S1's table; `driftlab-cli iso230-2 --json` gives
   the ISO 230-2 mean deviations it was made from.
3. A simulated one-axis LinuxCNC 2.9 loads the table ([JOINT_0]COMP_FILE,
   COMP_FILE_TYPE), homes, and goes to positions on and between table points,
   each approached from below and from above.
4. At each, the correction LinuxCNC applies, joint.0.motor-pos-cmd -
   joint.0.pos-cmd (less motor-offset, 0 here), is added to the simulated
   error there, the deviation DriftLab measured interpolated linearly between
   targets: the residual, what is left of the error at the compensated
   position, must be within 1 um of zero. Bidirectional table: the error is
   x_up(x) approaching from below, x_down(x) from above; unidirectional:
   x_mean(x) +/- B_mean/2, the backlash B_mean being folded into the two
   columns (docs/compensation.md).

--wrong-sign is the check's own check: the table LinuxCNC loads is
DriftLab's CSV written with --sign error, its error columns taken as the
type 1 trims (an integrator's sign mistake). LinuxCNC then adds the error
instead of removing it, the residual is twice the error, and the test passes
only when the check above fails at every point where the error is larger
than the tolerance, with a residual of twice the error (within 1 um).

Usage: comp_acceptance.py --cli DRIFTLAB_CLI --format linuxcnc|linuxcnc-type1
       [--sign correction|error] [--bidirectional] [--spacing MM] [--wrong-sign]
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


def simulated_error(iso, bidirectional):
    """Per direction, the error in um at each target that the table must
    cancel: what the axis does there without compensation."""
    targets = iso["targets"]
    if bidirectional:
        up = [(t["target_mm"], t["mean_up"]) for t in targets]
        down = [(t["target_mm"], t["mean_down"]) for t in targets]
    else:
        half_b = iso["B_mean"] / 2
        up = [(t["target_mm"], t["mean"] + half_b) for t in targets]
        down = [(t["target_mm"], t["mean"] - half_b) for t in targets]
    return {"+": up, "-": down}


def wrong_sign_table(csv_path, table_path):
    """DriftLab's error CSV (position_mm,error_um,error_minus_um,...) written
    as a COMP_FILE_TYPE 1 table, the errors taken as trims."""
    with open(csv_path) as f:
        lines = f.read().splitlines()
    header = lines[0].split(",")
    if header[:3] != ["position_mm", "error_um", "error_minus_um"]:
        raise SystemExit("unexpected CSV header %s" % lines[0])
    with open(table_path, "w") as out:
        for line in lines[1:]:
            x, up, down = (float(v) for v in line.split(",")[:3])
            out.write("%.4f %.4f %.4f\n" % (x, up / 1000, down / 1000))


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
    parser.add_argument("--sign", choices=("correction", "error"))
    parser.add_argument("--wrong-sign", action="store_true")
    args = parser.parse_args()
    if args.wrong_sign and (args.format != "linuxcnc-type1" or not args.bidirectional):
        parser.error("--wrong-sign builds a bidirectional type 1 table")
    lcnc_sim.skip_unless_available()

    with tempfile.TemporaryDirectory(prefix="driftlab-comp-") as work:
        campaign = os.path.join(work, "campaign")
        cli(args.cli, "simulate", "--out", campaign, "--runs", "S1", "--seed", "1")
        table = os.path.join(work, "x.comp")
        options = []
        if args.bidirectional:
            options.append("--bidirectional")
        if args.spacing:
            options += ["--spacing", args.spacing]
        if args.wrong_sign:
            errors = os.path.join(work, "errors.csv")
            cli(args.cli, "compensate", campaign, "--run", "S1", "--format", "csv",
                "--sign", "error", "--out", errors, *options)
            wrong_sign_table(errors, table)
        else:
            if args.sign:
                options += ["--sign", args.sign]
            cli(args.cli, "compensate", campaign, "--run", "S1", "--format", args.format,
                "--out", table, *options)
        iso = json.loads(cli(args.cli, "iso230-2", campaign, "--run", "S1", "--json"))
        with open(table) as f:
            rows = f.read().splitlines()
        comp_type = 0 if args.format == "linuxcnc" else 1
        print("table %s (COMP_FILE_TYPE %d, %s, sign %s%s, %d rows): first %s, last %s"
              % (args.format, comp_type,
                 "bidirectional" if args.bidirectional else "unidirectional",
                 args.sign or "default", ", WRONG SIGN" if args.wrong_sign else "",
                 len(rows), rows[0], rows[-1]))

        error = simulated_error(iso, args.bidirectional)
        positions = test_positions([t["target_mm"] for t in iso["targets"]])
        code, output, result, seconds = lcnc_sim.run(
            "comp_display.py", {"positions_mm": positions, "approach_mm": APPROACH_MM},
            joint_extra="COMP_FILE = %s\nCOMP_FILE_TYPE = %d" % (table, comp_type))
    print("LinuxCNC run: %.1f s, exit %d" % (seconds, code))
    if code != 0 or result is None:
        print(output)
        print("FAIL: LinuxCNC run did not complete")
        return 1
    failures, checked = judge(result["readings"], error, 2 * len(positions))
    if not args.wrong_sign:
        return 1 if failures else 0
    return judge_wrong_sign(failures, checked)


def judge(readings, error, count):
    """(failures, [(error_um, residual_um)]): the residual is the error left
    at the compensated position, the error plus LinuxCNC's correction."""
    print("%-12s %-4s %-14s %-14s %-12s" % ("position_mm", "dir", "correction_um",
                                            "error_um", "residual_um"))
    failures, largest_um, checked = 0, 0.0, []
    for r in readings:
        x, direction = r["position_mm"], r["direction"]
        if abs(r["joint.0.pos-cmd"] - x) > 1e-9:
            print("FAIL: joint at %.6f mm, not %.4f" % (r["joint.0.pos-cmd"], x))
            failures += 1
        correction_um = (r["joint.0.motor-pos-cmd"] - r["joint.0.pos-cmd"]
                         - r["joint.0.motor-offset"]) * 1000
        error_um = interpolated(error[direction], x)
        residual_um = error_um + correction_um
        checked.append((error_um, residual_um))
        largest_um = max(largest_um, abs(error_um))
        bad = abs(residual_um) > TOLERANCE_UM
        failures += bad
        print("%-12.4f %-4s %-14.3f %-14.3f %-12.3f%s" % (x, direction, correction_um,
                                                           error_um, residual_um,
                                                           "  FAIL" if bad else ""))
    # A table LinuxCNC ignored would leave the whole error: only an error well
    # above the tolerance proves the table was applied.
    if len(readings) != count:
        print("FAIL: %d readings, not %d" % (len(readings), count))
        failures += 1
    if largest_um < 5 * TOLERANCE_UM:
        print("FAIL: the largest simulated error is %.3f um: too small to tell "
              "an applied table from none" % largest_um)
        failures += 1
    print("%d readings, %d beyond %.1f um or off position" % (len(readings), failures,
                                                            TOLERANCE_UM))
    return failures, checked


def judge_wrong_sign(failures, checked):
    """The wrong-sign table must be caught: the check fails wherever the error
    exceeds the tolerance, and the residual is twice the error."""
    wrong = 0
    for error_um, residual_um in checked:
        caught = abs(residual_um) > TOLERANCE_UM or abs(error_um) <= TOLERANCE_UM
        doubled = abs(residual_um - 2 * error_um) <= TOLERANCE_UM
        wrong += not (caught and doubled)
    if failures == 0 or wrong:
        print("FAIL: the wrong-sign table was not caught (%d failures, %d readings where the "
              "residual is not twice the error)" % (failures, wrong))
        return 1
    print("wrong sign caught: %d failures, residual twice the error everywhere" % failures)
    return 0


if __name__ == "__main__":
    sys.exit(lcnc_sim.quiet_unless_failed(main))
