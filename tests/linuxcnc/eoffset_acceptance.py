#!/usr/bin/python3
"""Acceptance test of DriftLab's live thermal offset on a real LinuxCNC.

A simulated one-axis LinuxCNC 2.9 loads resources/linuxcnc/driftlab_eoffset.hal
(the component serving the register map's blocks 0 and 3 over Modbus TCP on
127.0.0.1, driving axis.x.eoffset-*). A Modbus client that is not the
component writes live offsets; with the axis at rest, once the ramp has
ended, the motor command minus the commanded position must equal the offset
within 1 um at every step: +12.345 um, a change, a write while cutting
(deferred), disable (back to 0), and a timeout (stale raised, offset held).

Usage: eoffset_acceptance.py (the writer is mbpoll; DriftLab's own writer is
tested by live_acceptance.py). Exit 0 pass, 1 fail, 77 skip.
"""

import argparse
import os
import socket
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lcnc_sim  # noqa: E402

TOLERANCE_UM = 1.0
RESOURCES = os.path.join(os.path.dirname(lcnc_sim.HERE), os.pardir, "resources", "linuxcnc")


def free_port():
    """A port nobody listens on now, on loopback only."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main():
    argparse.ArgumentParser(description=__doc__).parse_args()
    lcnc_sim.skip_unless_available()
    if not os.path.exists("/usr/bin/mbpoll"):
        print("FAIL: /usr/bin/mbpoll (Debian mbpoll) is missing: it is in "
              "packaging/debian-packages.txt")
        return 1
    writer = {"kind": "mbpoll"}
    resources = os.path.realpath(RESOURCES)
    port = free_port()
    code, output, result, seconds = lcnc_sim.run(
        "eoffset_display.py", {"port": port, "writer": writer},
        halfiles=[os.path.join(resources, "driftlab_eoffset.hal")],
        axis_extra="OFFSET_AV_RATIO = 0.2",
        extra_sections="[DRIFTLAB]\nEOFFSET = %s\nMODBUS_BIND = 127.0.0.1\nMODBUS_PORT = %d\n"
        % (os.path.join(resources, "driftlab_eoffset.py"), port))
    print("writer: %s; LinuxCNC run: %.1f s, exit %d" % (writer["kind"], seconds, code))
    if code != 0 or result is None:
        print(output)
        print("FAIL: LinuxCNC run did not complete")
        return 1
    return judge(result["steps"])


def judge(steps):
    print("%-40s %-10s %-12s %-10s %-6s %-6s" % ("step", "wanted_um", "motor-cmd_um",
                                                  "error_um", "stale", "state"))
    failures = 0
    for s in steps:
        applied_um = (s["joint.0.motor-pos-cmd"] - s["commanded_mm"]
                      - s["joint.0.motor-offset"]) * 1000
        wanted_um = s["wanted_nm"] / 1000
        error_um = applied_um - wanted_um
        problems = []
        if abs(error_um) > TOLERANCE_UM:
            problems.append("offset")
        want_stale = 1 if s["step"].startswith("no update") else 0
        if s["stale"] != want_stale or s.get("stale_pin", want_stale) != want_stale:
            problems.append("stale")
        if (s["magic"], s["map_version"]) != (0x4446, 1):
            problems.append("block 0 identity")
        want_state = 2 if "while cutting" in s["step"] else 0
        if s["machine_state"] != want_state:
            problems.append("machine_state")
        failures += bool(problems)
        print("%-40s %-10.3f %-12.3f %-10.3f %-6d %-6d%s" % (
            s["step"], wanted_um, applied_um, error_um, s["stale"], s["machine_state"],
            "  FAIL: " + ", ".join(problems) if problems else ""))
    print("%d steps, %d failed" % (len(steps), failures))
    return 1 if failures or len(steps) < 8 else 0


if __name__ == "__main__":
    sys.exit(lcnc_sim.quiet_unless_failed(main))
