#!/usr/bin/python3
"""A tiny socat for the RTU tests: two pseudo-terminals joined back to back,
like a null-modem cable between two serial ports. Stdlib only.

    python3 pty_bridge.py

Prints the two slave paths (one per line), then copies bytes between the two
masters until killed. A side nobody has open (its slave closed: the master
reports a hang-up) drops what is sent to it, as a cable with nothing plugged in
would; so a peer that is killed and started again does not read requests left
over from before. Both slaves are put in raw mode first, so no byte is echoed
or translated before a program opens and configures its end.
"""
import os
import select
import sys
import time
import tty


def hung_up(master):
    """Whether nobody has the slave of `master` open."""
    probe = select.poll()
    probe.register(master, select.POLLIN)
    return any(revents & select.POLLHUP for _, revents in probe.poll(0))


def main():
    ends = []
    for _ in range(2):
        master, slave = os.openpty()
        tty.setraw(slave)
        ends.append((master, os.ttyname(slave)))
        # Closed here: the master then reports a hang-up until a program opens
        # the slave path, which is how a side tells "nobody there".
        os.close(slave)
    for _, path in ends:
        print(path)
    sys.stdout.flush()

    masters = [m for m, _ in ends]
    poller = select.poll()
    for m in masters:
        poller.register(m, select.POLLIN)
    while True:
        events = dict(poller.poll(20))
        idle_hangup = False
        for m in masters:
            revents = events.get(m, 0)
            if not revents & select.POLLIN:
                idle_hangup |= bool(revents & select.POLLHUP)
                continue
            try:
                data = os.read(m, 4096)
            except OSError:  # EIO: nobody has this side open
                idle_hangup = True
                continue
            other = masters[1] if m == masters[0] else masters[0]
            # Asked now, not at the last poll: a side opened a moment ago
            # gets what is sent to it from then on.
            if data and not hung_up(other):
                os.write(other, data)
        if idle_hangup:
            time.sleep(0.005)  # a hung-up master polls ready at once: do not spin

if __name__ == "__main__":
    main()
