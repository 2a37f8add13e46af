#!/usr/bin/python3
"""LinuxCNC display for the live-offset test: with driftlab_eoffset loaded
(resources/linuxcnc/driftlab_eoffset.hal), a Modbus client writes live
offsets; the axis rests at X = REST_MM and we record where the motion
controller puts the motor once the offset has ramped in. The test
(eoffset_acceptance.py) judges the numbers."""

import os
import sys
import time
import traceback

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lcnc_control  # noqa: E402
import modbus_clients  # noqa: E402

REST_MM = 300.0
HOST = "127.0.0.1"
LONG_TIMEOUT_S = 600  # no stale flag while the steps run
PINS = ("joint.0.motor-pos-cmd", "joint.0.pos-cmd", "joint.0.motor-offset", "axis.x.eoffset",
        "axis.x.eoffset-request")


class Run:
    def __init__(self, plan):
        self.port = plan["port"]
        self.machine = lcnc_control.Machine()
        self.writer = modbus_clients.make_writer(plan["writer"], HOST, self.port)
        self.steps = []

    def registers(self, address, count):
        return modbus_clients.read_registers(HOST, self.port, address, count)

    def settle(self, offset_nm):
        """Waits until LinuxCNC took the offset and its ramp ended."""
        m = self.machine
        lcnc_control.wait_for(
            lambda: abs(m.pin("axis.x.eoffset-request") * 1e6 - offset_nm) < 0.5
            and abs(m.pin("axis.x.eoffset") - m.pin("axis.x.eoffset-request")) < 1e-6,
            lambda: "external offset %d nm within 1 nm (%s)" % (offset_nm, self.pins_now()))
        return m.settled(PINS)

    def pins_now(self):
        names = PINS + tuple("driftlab-eoffset." + p for p in (
            "counts", "enable", "offset-nm", "request", "machine-on", "homed", "stale"))
        return ", ".join("%s=%s" % (n, self.machine.pin(n)) for n in names)

    def record(self, name, wanted_nm, pins, **extra):
        live = self.registers(modbus_clients.REG_SEQUENCE, 6)
        state = self.registers(0, 3)
        self.steps.append(dict(step=name, wanted_nm=wanted_nm, commanded_mm=REST_MM,
                               sequence=live[0], stale=live[5], magic=state[0],
                               map_version=state[1], machine_state=state[2], **pins, **extra))

    def write_and_record(self, name, offset_nm, enable, timeout_s=LONG_TIMEOUT_S):
        self.writer.write(offset_nm, enable, timeout_s)
        wanted_nm = offset_nm if enable else 0
        self.record(name, wanted_nm, self.settle(wanted_nm))


def main():
    plan = lcnc_control.load_plan()
    run = Run(plan)
    m = run.machine
    m.start()
    m.move_to(REST_MM)
    run.record("at rest, nothing written", 0, m.settled(PINS))
    run.write_and_record("offset +12.345 um, enable", 12345, True)
    run.write_and_record("change to -7.500 um", -7500, True)

    # Cutting (spindle on, as the HAL snippet wires it): a new offset waits.
    m.mdi("M3 S1000")
    lcnc_control.wait_for(lambda: run.registers(0, 3)[2] == 2, "machine_state 2 (cutting)")
    run.writer.write(20000, True, LONG_TIMEOUT_S)
    time.sleep(0.5)  # 25 component cycles: time to (wrongly) apply it
    run.record("+20 um written while cutting", -7500, m.settled(PINS))
    m.mdi("M5")
    run.record("spindle off: +20 um applied", 20000, run.settle(20000))

    run.write_and_record("disable", 0, False)

    # Stale: a 1 s timeout and no new sequence. The offset must be held.
    run.write_and_record("offset +5 um, timeout 1 s", 5000, True, timeout_s=1)
    lcnc_control.wait_for(lambda: run.registers(modbus_clients.REG_STALE, 1)[0] == 1,
                          "live_stale = 1")
    run.record("no update for the timeout: stale, held", 5000, m.settled(PINS),
               stale_pin=m.pin("driftlab-eoffset.stale"))
    run.write_and_record("a new update clears stale", 5000, True)
    lcnc_control.write_result(plan, {"steps": run.steps})
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except Exception:  # the test reads the reason from LinuxCNC's output
        traceback.print_exc()
        sys.exit(1)
