"""Modbus TCP clients of the live-offset test, independent of the component.

The writer of eoffset_acceptance.py is Debian's mbpoll; DriftLab's own
writer (`driftlab-cli live --push`) is tested by live_acceptance.py. The
reader is always mbpoll, so a check never trusts the writer under test.
"""

import re
import subprocess

MBPOLL = "/usr/bin/mbpoll"
REG_SEQUENCE, REG_OFFSET, REG_ENABLE, REG_STALE = 2000, 2001, 2003, 2005


def mbpoll(host, port, address, *args):
    """mbpoll numbers references from 1: -r is the protocol address + 1."""
    argv = [MBPOLL, "-m", "tcp", "-a", "1", "-p", str(port), "-1", "-o", "2",
            "-r", str(address + 1), *args]
    argv.insert(argv.index("-r"), host)  # the host goes before the values
    done = subprocess.run(argv, capture_output=True, text=True, timeout=30)
    if done.returncode != 0:
        raise RuntimeError("%s: %s%s" % (" ".join(argv), done.stdout, done.stderr))
    return done.stdout


def read_registers(host, port, address, count):
    out = mbpoll(host, port, address, "-c", str(count))
    values = [int(v) for _, v in re.findall(r"^\[(\d+)\]:\s+(-?\d+)", out, re.M)]
    if len(values) != count:
        raise RuntimeError("mbpoll read %d of %d registers:\n%s" % (len(values), count, out))
    return values


class MbpollWriter:
    """Writes block 3 as the map asks of a writer that takes several requests:
    offset (int32, high word first: -B), enable and timeout, then the new
    sequence last, since the component latches an update on the sequence."""

    def __init__(self, host, port):
        self.host, self.port, self.sequence = host, port, 0

    def write(self, offset_nm, enable, timeout_s):
        self.sequence = self.sequence % 65535 + 1
        mbpoll(self.host, self.port, REG_OFFSET, "-t", "4:int", "-B", "--", str(offset_nm))
        mbpoll(self.host, self.port, REG_ENABLE, "-t", "4", str(int(enable)), str(timeout_s))
        mbpoll(self.host, self.port, REG_SEQUENCE, "-t", "4", str(self.sequence))


def make_writer(spec, host, port):
    if spec["kind"] == "mbpoll":
        return MbpollWriter(host, port)
    raise ValueError("unknown writer " + spec["kind"])
