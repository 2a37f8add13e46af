#!/usr/bin/python3
"""An independent controller of DriftLab's Modbus register map
(docs/modbus-register-map.md), written against the document with Debian's
python3-pymodbus (3.0), not against DriftLab's C++: the push test talks to it
to show that the map, not one implementation, is what DriftLab speaks.

    /usr/bin/python3 pymodbus_controller.py [--port N] [--capacity N]
        [--position-mm X] [--feed-mm-min F] [--torque-nm T] [--state S]

Serves the axis state given (registers 8-13: report flag, position int32 in
0.1 um, feed int32 in 0.1 mm/min, torque int16 in 0.01 N m, each rounded half
away from zero; machine state in register 2). Prints the TCP port it listens on (127.0.0.1) as its first line, then serves
until killed. The checksum is pymodbus's own CRC (pymodbus.utilities.computeCRC),
which returns the CRC byte-swapped for RTU frames; the map holds it unswapped.
"""
import argparse
import asyncio
import struct
from decimal import ROUND_HALF_UP, Decimal

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusSlaveContext
from pymodbus.utilities import computeCRC

from pymodbus_serve import serve_on_loopback

MAGIC, MAP_VERSION = 0x4446, 1
MACHINE_STATE, CAPACITY, ACTIVE_VERSION, COMMIT_STATUS, ACK_VERSION, PREVIOUS_VERSION = 2, 3, 4, 5, 6, 7
AXIS_REPORT, POSITION, FEED, TORQUE = 8, 9, 11, 13
STATES = {"idle": 0, "moving": 1, "cutting": 2, "tool-change": 3}
STAGED, COMMAND, STAGED_DATA, ACTIVE, ACTIVE_DATA = 100, 108, 200, 1000, 1100
HEADER = 8
CUTTING = 2
STAGED_OK, APPLIED, REFUSED, CHECKSUM_MISMATCH, ABORTED, ROLLED_BACK = 1, 2, 3, 4, 5, 6
COMMIT, ABORT, ROLL_BACK = 1, 2, 3


def counts(value, per_unit):
    """value x per_unit rounded half away from zero (Python's round() is
    half to even; the map says away from zero)."""
    scaled = Decimal(repr(value)) * per_unit
    return int(scaled.to_integral_value(rounding=ROUND_HALF_UP))


def axis_registers(position_mm, feed_mm_min, torque_nm):
    """Registers 9-13, packed by struct: big-endian int32 = high word first."""
    return list(struct.unpack(">HHHHH", struct.pack(
        ">iih", counts(position_mm, 10000), counts(feed_mm_min, 10), counts(torque_nm, 100))))


def crc16_modbus(registers):
    swapped = computeCRC(b"".join(struct.pack(">H", r) for r in registers))
    return ((swapped & 0xFF) << 8) | (swapped >> 8)


class ControllerMap(ModbusSequentialDataBlock):
    """Holding registers 0..2005 that act on the command register when written."""

    def __init__(self, capacity, axis=(0.0, 0.0, 0.0), state="idle"):
        super().__init__(0, [0] * 2006)
        self.capacity = capacity
        self.values[AXIS_REPORT] = 1
        self.values[POSITION:TORQUE + 1] = axis_registers(*axis)
        self.values[MACHINE_STATE] = STATES[state]
        self.pending = False
        self.previous = None  # (header, data) of the table before the active one
        self.values[0], self.values[1], self.values[CAPACITY] = MAGIC, MAP_VERSION, capacity

    def table(self, header_at, data_at):
        header = self.values[header_at:header_at + HEADER]
        points = min(header[1], self.capacity)
        data = self.values[data_at:data_at + points]
        if header[6] & 1:
            data += self.values[data_at + self.capacity:data_at + self.capacity + points]
        return header, data

    def put(self, header_at, data_at, table):
        header, data = table if table else ([0] * HEADER, [])
        self.values[header_at:header_at + HEADER] = header
        self.values[data_at:data_at + 2 * self.capacity] = [0] * (2 * self.capacity)
        points = header[1]
        self.values[data_at:data_at + min(points, len(data))] = data[:points]
        if header[6] & 1:
            start = data_at + self.capacity
            self.values[start:start + points] = data[points:]

    def answer(self, status, version):
        self.values[COMMIT_STATUS], self.values[ACK_VERSION] = status, version

    def setValues(self, address, values):  # pylint: disable=invalid-name
        super().setValues(address, values)
        count = len(values) if isinstance(values, list) else 1
        if address <= COMMAND < address + count:
            command, self.values[COMMAND] = self.values[COMMAND], 0
            {COMMIT: self.commit, ABORT: self.abort, ROLL_BACK: self.roll_back}.get(
                command, lambda: None)()

    def commit(self):
        header, data = self.table(STAGED, STAGED_DATA)
        version, points = header[0], header[1]
        if version == 0 or not 2 <= points <= self.capacity:
            return self.answer(REFUSED, version)
        if crc16_modbus(header[:7] + data) != header[7]:
            return self.answer(CHECKSUM_MISMATCH, version)
        self.pending = True
        self.answer(STAGED_OK, version)
        self.scan()

    def scan(self):
        if self.pending and self.values[MACHINE_STATE] != CUTTING:
            active = self.table(ACTIVE, ACTIVE_DATA)
            self.previous = active if active[0][0] else None
            staged = self.table(STAGED, STAGED_DATA)
            self.put(ACTIVE, ACTIVE_DATA, staged)
            self.values[ACTIVE_VERSION] = staged[0][0]
            self.values[PREVIOUS_VERSION] = self.previous[0][0] if self.previous else 0
            self.pending = False
            self.answer(APPLIED, staged[0][0])

    def abort(self):
        if self.pending:
            self.answer(ABORTED, self.values[STAGED])
        self.pending = False
        self.put(STAGED, STAGED_DATA, None)

    def roll_back(self):
        undone = self.values[ACTIVE_VERSION]
        self.put(ACTIVE, ACTIVE_DATA, self.previous)
        self.values[ACTIVE_VERSION] = self.previous[0][0] if self.previous else 0
        self.values[PREVIOUS_VERSION] = 0
        self.previous = None
        self.answer(ROLLED_BACK, undone)


async def serve(port, block):
    await serve_on_loopback(ModbusSlaveContext(hr=block, zero_mode=True), port)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--port", type=int, default=0, help="TCP port (0: a free one)")
    parser.add_argument("--capacity", type=int, default=256)
    parser.add_argument("--position-mm", type=float, default=0.0)
    parser.add_argument("--feed-mm-min", type=float, default=0.0)
    parser.add_argument("--torque-nm", type=float, default=0.0)
    parser.add_argument("--state", choices=sorted(STATES), default="idle")
    args = parser.parse_args()
    block = ControllerMap(args.capacity, (args.position_mm, args.feed_mm_min, args.torque_nm),
                          args.state)
    asyncio.run(serve(args.port, block))


if __name__ == "__main__":
    main()
