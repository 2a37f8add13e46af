"""Display-side helpers: what a test display does to the running LinuxCNC.

Imported by the display scripts, which LinuxCNC starts as
`SCRIPT -ini INI`; they run under /usr/bin/python3 (LinuxCNC's `linuxcnc`
and `hal` modules live there).
"""

import json
import os
import sys
import time

import hal
import linuxcnc

# Waits are bounds on how long a broken machine may hang the test, not
# assertions on speed.
WAIT_S = 10.0


def load_plan():
    """The plan.json the test wrote beside the INI named by -ini."""
    ini = sys.argv[sys.argv.index("-ini") + 1]
    with open(os.path.join(os.path.dirname(ini), "plan.json")) as f:
        return json.load(f)


def write_result(plan, result):
    with open(plan["result"], "w") as f:
        json.dump(result, f, indent=1)


def wait_for(condition, what, timeout_s=WAIT_S, period_s=0.01):
    deadline = time.monotonic() + timeout_s
    while not condition():
        if time.monotonic() > deadline:
            raise RuntimeError("gave up waiting for " + (what() if callable(what) else what))
        time.sleep(period_s)


class Machine:
    def __init__(self):
        # A HAL component of our own: hal.get_value needs one.
        self.component = hal.component("driftlab-test")
        self.component.ready()
        self.stat = linuxcnc.stat()
        self.command = linuxcnc.command()
        self.errors = linuxcnc.error_channel()

    def pin(self, name):
        return hal.get_value(name)

    def check_errors(self):
        error = self.errors.poll()
        if error and error[0] in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            raise RuntimeError("LinuxCNC: " + error[1])

    def _state_is(self, field, value):
        self.stat.poll()
        return getattr(self.stat, field) == value

    def start(self):
        """Machine on, joint 0 homed, MDI mode."""
        self.command.state(linuxcnc.STATE_ESTOP_RESET)
        self.command.state(linuxcnc.STATE_ON)
        wait_for(lambda: self._state_is("task_state", linuxcnc.STATE_ON), "machine on")
        self.command.mode(linuxcnc.MODE_MANUAL)
        self.command.wait_complete()
        self.command.home(-1)
        wait_for(lambda: self.pin("joint.0.homed"), "joint 0 homed")
        self.command.mode(linuxcnc.MODE_MDI)
        self.command.wait_complete()
        wait_for(lambda: self._state_is("task_mode", linuxcnc.MODE_MDI), "MDI mode")
        self.check_errors()

    def mdi(self, line):
        self.command.mdi(line)
        self.command.wait_complete()
        wait_for(lambda: self._state_is("interp_state", linuxcnc.INTERP_IDLE), line)
        self.check_errors()

    def move_to(self, x_mm):
        """A rapid in machine coordinates, returning when the joint is there."""
        self.mdi("G90 G53 G0 X%.6f" % x_mm)
        wait_for(lambda: abs(self.pin("joint.0.pos-cmd") - x_mm) < 1e-9
                 and self.pin("motion.in-position"), "X at %.6f" % x_mm)

    def settled(self, names, period_s=0.02, tolerance=1e-9):
        """The pins' values once two reads period_s apart agree (LinuxCNC
        ramps compensation and external offsets after the move ends)."""
        previous = [self.pin(n) for n in names]
        deadline = time.monotonic() + WAIT_S
        while time.monotonic() < deadline:
            time.sleep(period_s)
            current = [self.pin(n) for n in names]
            if all(abs(a - b) <= tolerance for a, b in zip(previous, current)):
                return dict(zip(names, current))
            previous = current
        raise RuntimeError("gave up waiting for %s to settle" % ", ".join(names))
