#!/usr/bin/python3
"""LinuxCNC display for live_acceptance.py: runs `driftlab-cli live --push`
against driftlab_eoffset while cutting and while not, and records where the
motion controller puts the motor."""

import json
import os
import subprocess
import sys
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoffset_display  # noqa: E402
import lcnc_control  # noqa: E402
import modbus_clients  # noqa: E402


def live(plan):
    """DriftLab's live compensation of run S3, fitted on S1, written to the
    component; returns its updates."""
    done = subprocess.run(
        [plan["cli"], "live", plan["campaign"], "--run", "S3", "--train", "S1", "--position",
         str(eoffset_display.REST_MM), "--interval-s", "300", "--push",
         "modbus://%s:%d" % (eoffset_display.HOST, plan["port"]), "--json"],
        capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise RuntimeError("driftlab-cli live failed: " + done.stderr)
    return json.loads(done.stdout)["updates"]


def main():
    plan = lcnc_control.load_plan()
    run = eoffset_display.Run(dict(plan, writer={"kind": "mbpoll"}))
    m = run.machine
    m.start()
    m.move_to(eoffset_display.REST_MM)
    steps = []

    def record(name, updates, wanted_um, pins):
        sequence = run.registers(modbus_clients.REG_SEQUENCE, 1)[0]
        steps.append(dict(step=name, updates=len(updates), sequence=sequence,
                          wanted_um=wanted_um, commanded_mm=eoffset_display.REST_MM, **pins))

    m.mdi("M3 S1000")
    lcnc_control.wait_for(lambda: run.registers(0, 3)[2] == 2, "machine_state 2 (cutting)")
    updates = live(plan)
    record("spindle on: nothing written", updates, 0.0, m.settled(eoffset_display.PINS))
    m.mdi("M5")
    lcnc_control.wait_for(lambda: run.registers(0, 3)[2] != 2, "machine_state not cutting")
    updates = live(plan)
    last_um = updates[-1]["offset_um"] if updates else 0.0
    # After a burst of updates LinuxCNC's offset ramp may end a few nm from
    # the request: wait for the request, then for the pins to stop moving,
    # and let the test judge within its 1 um.
    lcnc_control.wait_for(
        lambda: abs(m.pin("axis.x.eoffset-request") * 1e3 - last_um) < 1e-3,
        "external offset request %.3f um" % last_um)
    record("spindle off: every update written", updates, last_um,
           m.settled(eoffset_display.PINS))
    lcnc_control.write_result(plan, {"steps": steps})
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception:
        traceback.print_exc()
        sys.exit(1)
