#!/usr/bin/python3
"""DriftLab live thermal offset for LinuxCNC 2.9: a userspace HAL component.

Serves DriftLab's Modbus TCP register map (docs/modbus-register-map.md)
block 0 (identity, machine_state) and block 3 (the live offset, registers
2000-2005) and drives one axis's external offset (axis.L.eoffset-*). The
integrator's HAL file (driftlab_eoffset.hal) wires it; docs/linuxcnc.md says
how and what the tests prove.

Runs under Debian's /usr/bin/python3 because LinuxCNC's `hal` module and
python3-pymodbus (3.0.0rc1) are installed there.
"""

import argparse
import asyncio
import logging
import signal
import sys
import time

import hal
from pymodbus.datastore import (ModbusServerContext, ModbusSlaveContext,
                                ModbusSparseDataBlock)
from pymodbus.server.async_io import ModbusTcpServer

MAGIC = 0x4446  # "DF": this register map is served here
MAP_VERSION = 1
CUTTING = 2  # machine_state value of the map
REG_STATE = 0  # block 0
REG_MACHINE_STATE = 2
REG_LIVE = 2000  # block 3: sequence, offset hi, offset lo, enable, timeout, stale
REG_STALE = 2005
# LinuxCNC drops eoffset-counts changes while the machine is off, unhomed or
# the offset disabled; a change it took shows up in eoffset-request within one
# servo period (1 ms). Waiting this long before correcting again keeps a
# change that is still on its way from being sent twice.
RESEND_AFTER_S = 0.1


def int32_from_words(high, low):
    """The map's int32: two registers, high word first, two's complement."""
    value = (high << 16) | low
    return value - (1 << 32) if value & 0x80000000 else value


class LiveOffset:
    """The map's block 3 semantics, independent of HAL and Modbus.

    A new live_sequence is one update: the offset, enable and timeout are
    latched together when the sequence changes, so a writer that writes the
    registers one request at a time writes the sequence last.
    """

    def __init__(self):
        # The registers start at 0, so a writer's first update has sequence >= 1.
        self.sequence = 0
        self.offset_nm = 0
        self.enable = False
        self.timeout_s = 0
        self.last_update_s = None
        self.applied_nm = 0  # what the axis is told to hold
        self.stale = False

    def step(self, registers, cutting, now_s):
        """registers: the six values of 2000-2005. Returns the wanted offset in nm."""
        sequence, high, low, enable, timeout_s = registers[:5]
        if sequence != self.sequence:
            self.sequence = sequence
            self.offset_nm = int32_from_words(high, low)
            self.enable = enable == 1
            self.timeout_s = timeout_s
            self.last_update_s = now_s
        # Stale: no new sequence for live_timeout_s (0 = no timeout). The offset
        # is held, not dropped: removing it is the writer's decision (enable=0).
        self.stale = (self.last_update_s is not None and self.timeout_s > 0
                      and now_s - self.last_update_s > self.timeout_s)
        # Never change the offset mid-cut (docs/compensation.md): a change that
        # arrives while cutting waits for the cut to end.
        if not cutting:
            self.applied_nm = self.offset_nm if self.enable else 0
        return self.applied_nm


class CountsDriver:
    """Turns a wanted offset into axis.L.eoffset-counts changes.

    LinuxCNC adds (counts - previous counts) * eoffset-scale to its requested
    offset, only while enabled, homed and the machine on, and zeroes that
    request at every machine-on. So the counts pin is not an absolute offset:
    we compare the wanted offset with axis.L.eoffset-request and send the
    difference, which also repairs any change LinuxCNC dropped.
    """

    def __init__(self):
        self.counts = 0
        self.last_send_s = -1e9

    def step(self, wanted_nm, request_nm, machine_on, homed, now_s):
        if not machine_on:
            # LinuxCNC's advice: counts at zero while the machine is off.
            self.counts = 0
            return self.counts
        if not homed or now_s - self.last_send_s < RESEND_AFTER_S:
            return self.counts
        delta = round(wanted_nm - request_nm)  # one count is 1 nm
        if delta != 0:
            # Wrap like the s32 pin so a long run cannot overflow it.
            self.counts = (self.counts + delta + 2**31) % 2**32 - 2**31
            self.last_send_s = now_s
        return self.counts


def make_pins(name):
    component = hal.component(name)
    pins = {
        # out: wire to the axis (see driftlab_eoffset.hal)
        "counts": (hal.HAL_S32, hal.HAL_OUT),  # -> axis.L.eoffset-counts
        "enable": (hal.HAL_BIT, hal.HAL_OUT),  # -> axis.L.eoffset-enable
        "scale": (hal.HAL_FLOAT, hal.HAL_OUT),  # -> axis.L.eoffset-scale
        "stale": (hal.HAL_BIT, hal.HAL_OUT),  # live_stale, for a warning
        "offset-nm": (hal.HAL_S32, hal.HAL_OUT),  # the offset wanted now
        # in
        "request": (hal.HAL_FLOAT, hal.HAL_IN),  # <- axis.L.eoffset-request, machine units
        "machine-on": (hal.HAL_BIT, hal.HAL_IN),  # <- motion.motion-enabled
        "homed": (hal.HAL_BIT, hal.HAL_IN),  # <- joint.N.homed (every joint)
        "machine-state": (hal.HAL_S32, hal.HAL_IN),  # 0 idle 1 moving 2 cutting 3 tool change
        "cutting": (hal.HAL_BIT, hal.HAL_IN),  # 1 overrides machine-state with 2
    }
    for pin, (kind, direction) in pins.items():
        component.newpin(pin, kind, direction)
    return component


def make_store(unit):
    registers = {REG_STATE: [MAGIC, MAP_VERSION] + [0] * 14,  # block 0: 0-15
                 REG_LIVE: [0] * 6}  # block 3: 2000-2005
    # zero_mode: the protocol address is the register number of the map
    # (pymodbus otherwise shifts every address by one).
    slave = ModbusSlaveContext(hr=ModbusSparseDataBlock(registers, mutable=False),
                               zero_mode=True)
    return ModbusServerContext(slaves={unit: slave}, single=False)


async def serve(args):
    component = make_pins(args.name)
    # One count is 1 nm, the map's unit, in the machine's own units.
    units_per_nm = 1e-6 if args.units in ("mm", "metric") else 1e-6 / 25.4
    component["scale"] = units_per_nm
    component["enable"] = True  # both applying and removing go through counts
    component.ready()
    store = make_store(args.unit)
    slave = store[args.unit]
    server = ModbusTcpServer(store, address=(args.bind, args.port),
                             allow_reuse_address=True)
    server_task = asyncio.create_task(server.serve_forever())
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for sig in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(sig, stop.set)
    live = LiveOffset()
    driver = CountsDriver()
    try:
        while not stop.is_set():
            if server_task.done():  # e.g. the port is taken: fail loudly
                server_task.result()
                raise RuntimeError("the Modbus server stopped")
            now_s = time.monotonic()
            state = 2 if component["cutting"] else component["machine-state"]
            slave.setValues(3, REG_MACHINE_STATE, [max(0, min(state, 0xFFFF))])
            wanted_nm = live.step(slave.getValues(3, REG_LIVE, 6), state == CUTTING, now_s)
            slave.setValues(3, REG_STALE, [int(live.stale)])
            component["stale"] = live.stale
            component["offset-nm"] = wanted_nm
            component["counts"] = driver.step(wanted_nm, component["request"] / units_per_nm,
                                              component["machine-on"], component["homed"],
                                              now_s)
            try:
                await asyncio.wait_for(stop.wait(), args.period)
            except asyncio.TimeoutError:
                pass
    finally:
        await server.shutdown()
        server_task.cancel()
        component.exit()


def main():
    # pymodbus 3.0.0rc1 logs every client that disconnects as an ERROR.
    logging.getLogger("pymodbus.server.async_io").setLevel(logging.CRITICAL)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--name", default="driftlab-eoffset", help="HAL component name")
    parser.add_argument("--bind", default="0.0.0.0", help="address to serve Modbus TCP on")
    parser.add_argument("--port", type=int, default=5020,
                        help="Modbus TCP port (502 needs root; LinuxCNC runs as a user)")
    parser.add_argument("--unit", type=int, default=1, help="Modbus unit id")
    parser.add_argument("--units", choices=("mm", "metric", "inch", "in", "imperial"),
                        default="mm",
                        help="the machine's linear units ([TRAJ]LINEAR_UNITS)")
    parser.add_argument("--period", type=float, default=0.02, help="update period in s")
    args = parser.parse_args()
    asyncio.run(serve(args))
    return 0


if __name__ == "__main__":
    sys.exit(main())
