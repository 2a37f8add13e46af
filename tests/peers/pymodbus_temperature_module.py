#!/usr/bin/python3
"""An independent temperature module for DriftLab's device tests, written with
Debian's python3-pymodbus (3.0) against docs/devices.md and
resources/devices/temperature-8ch-pt100.json, not against DriftLab's C++.

    /usr/bin/python3 pymodbus_temperature_module.py [--port N]
    /usr/bin/python3 pymodbus_temperature_module.py --rtu DEVICE [--baud N] [--parity N|E|O]

TCP: prints the port it listens on (127.0.0.1) as its first line. RTU: serves
Modbus RTU (pymodbus's serial server and RTU framer, unit 1, 8 data bits,
1 stop bit) on the serial DEVICE, e.g. a pty of tests/peers/pty_bridge.py,
and prints "ready" once the device is open. Either way it serves until killed. The values are fixed so that a test knows what it must read:

input registers 0..7 (the 8-channel profile: int16 in 0.1 degC)
    21.5, -12.3, 0.0, 100.0, open (0x7FFF), short (0x8000), 25.3, 3276.6
holding registers 100.. (word orders and 32-bit types)
    100-101 float32 21.5 high word first    102-103 float32 21.5 low word first
    104-105 int32 -123456 high word first   106-107 uint32 3000000000 low first
    108     uint16 65000
"""
import argparse
import asyncio
import struct

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusSlaveContext

from pymodbus_serve import serve_on_loopback

PROFILE_DEGC = [21.5, -12.3, 0.0, 100.0, None, None, 25.3, 3276.6]
OPEN, SHORT = 0x7FFF, 0x8000


def int16_word(value):
    return struct.unpack(">H", struct.pack(">h", value))[0]


def words(fmt, value):
    """The two registers of a 32-bit value, high word first."""
    return list(struct.unpack(">HH", struct.pack(fmt, value)))


def input_registers():
    regs = [int16_word(round(v * 10)) if v is not None else 0 for v in PROFILE_DEGC]
    regs[4], regs[5] = OPEN, SHORT
    return regs


def holding_registers():
    regs = [0] * 110
    regs[100:102] = words(">f", 21.5)
    regs[102:104] = list(reversed(words(">f", 21.5)))
    regs[104:106] = words(">i", -123456)
    regs[106:108] = list(reversed(words(">I", 3000000000)))
    regs[108] = 65000
    return regs


def slave_context():
    return ModbusSlaveContext(ir=ModbusSequentialDataBlock(0, input_registers()),
                              hr=ModbusSequentialDataBlock(0, holding_registers()),
                              zero_mode=True)


async def serve_rtu(device, baud, parity):
    # Imported here: the TCP peer does not need pyserial.
    from pymodbus.datastore import ModbusServerContext
    from pymodbus.server.async_io import ModbusSerialServer
    from pymodbus.transaction import ModbusRtuFramer

    server = ModbusSerialServer(ModbusServerContext(slaves={1: slave_context()}, single=False),
                                ModbusRtuFramer, port=device, baudrate=baud, parity=parity,
                                bytesize=8, stopbits=1, timeout=0.05)
    await server.start()
    if server.transport is None:
        raise SystemExit(f"cannot open {device}")
    print("ready", flush=True)
    await server.serve_forever()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--port", type=int, default=0, help="TCP port (0: a free one)")
    parser.add_argument("--rtu", metavar="DEVICE", help="serve Modbus RTU on this serial device")
    parser.add_argument("--baud", type=int, default=19200)
    parser.add_argument("--parity", choices=["N", "E", "O"], default="N")
    args = parser.parse_args()
    if args.rtu:
        asyncio.run(serve_rtu(args.rtu, args.baud, args.parity))
    else:
        asyncio.run(serve_on_loopback(slave_context(), args.port))


if __name__ == "__main__":
    main()
