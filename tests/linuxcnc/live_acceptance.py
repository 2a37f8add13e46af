#!/usr/bin/python3
"""Acceptance test of DriftLab's own live compensation on a real LinuxCNC.

`driftlab-cli live --push` replays a simulated run (the heat-transfer model
fitted on S1, run S3 replayed) and writes every update to the register map's
block 3, served by resources/linuxcnc/driftlab_eoffset.py inside a simulated
one-axis LinuxCNC 2.9; it reads the machine state from block 0, which the
component takes from LinuxCNC (spindle on = cutting).

1. Spindle on: DriftLab sees "cutting" at every step and writes nothing: the
   sequence stays 0 and the motor command equals the commanded position.
2. Spindle off: every update is written; once the ramp has ended, the motor
   command minus the commanded position equals DriftLab's last offset within
   1 um, and the sequence equals the number of updates.

Usage: live_acceptance.py --cli DRIFTLAB_CLI. Exit 0 pass, 1 fail, 77 skip.
"""

import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoffset_acceptance  # noqa: E402
import lcnc_sim  # noqa: E402

TOLERANCE_UM = 1.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    args = parser.parse_args()
    lcnc_sim.skip_unless_available()
    resources = os.path.realpath(eoffset_acceptance.RESOURCES)
    with tempfile.TemporaryDirectory(prefix="driftlab-live-") as work:
        campaign = os.path.join(work, "campaign")
        subprocess.run([args.cli, "simulate", "--out", campaign, "--runs", "S1,S3", "--seed",
                        "1"], check=True, capture_output=True)
        port = eoffset_acceptance.free_port()
        code, output, result, seconds = lcnc_sim.run(
            "live_display.py", {"port": port, "cli": args.cli, "campaign": campaign},
            halfiles=[os.path.join(resources, "driftlab_eoffset.hal")],
            axis_extra="OFFSET_AV_RATIO = 0.2",
            extra_sections="[DRIFTLAB]\nEOFFSET = %s\nMODBUS_BIND = 127.0.0.1\n"
            "MODBUS_PORT = %d\n" % (os.path.join(resources, "driftlab_eoffset.py"), port))
    print("LinuxCNC run: %.1f s, exit %d" % (seconds, code))
    if code != 0 or result is None:
        print(output)
        print("FAIL: LinuxCNC run did not complete")
        return 1
    failures = 0
    for s in result["steps"]:
        applied_um = (s["joint.0.motor-pos-cmd"] - s["commanded_mm"]
                      - s["joint.0.motor-offset"]) * 1000
        error_um = applied_um - s["wanted_um"]
        bad = abs(error_um) > TOLERANCE_UM or s["sequence"] != s["updates"]
        failures += bad
        print("%-34s updates %3d  sequence %3d  DriftLab %9.3f um  LinuxCNC %9.3f um  "
              "error %6.3f um%s" % (s["step"], s["updates"], s["sequence"], s["wanted_um"],
                                     applied_um, error_um, "  FAIL" if bad else ""))
    cutting, idle = result["steps"]
    if cutting["updates"] != 0 or idle["updates"] < 10 or abs(idle["wanted_um"]) < 5:
        print("FAIL: expected no update while cutting and a real offset after it")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(lcnc_sim.quiet_unless_failed(main))
