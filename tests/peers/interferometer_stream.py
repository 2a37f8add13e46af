#!/usr/bin/python3
"""A laser interferometer streaming DriftLab's line protocol
(docs/interferometer.md), written from the document, stdlib only.

    python3 interferometer_stream.py --scenario good|bad-line|close-mid|compensated
    python3 interferometer_stream.py --scenario plan --readings FILE [--drop-after N]

Listens on 127.0.0.1 (at --port, 0: a free one), prints the port as its first
line, serves one connection and exits. The bytes go out in small chunks that
cut lines in the middle, as a real serial-to-TCP bridge does.

`plan` streams the readings of FILE (one per line: send_at_s,position_mm,
deviation_um; send_at_s counted from the first connection) as an
interferometer with its compensation off, referenced to standard air, in
standard air (20 degC, 101325 Pa, 50 %RH): each at its time, then an env line
every second until the reader goes away. With --drop-after N the connection
is cut after N readings (mid-line, no `end`), and the readings after them go
to the next connection, which starts a new stream with its header.
"""
import argparse
import socket
import time

HEADER_OFF = "header,compensation=off,reference=vacuum"
HEADER_ON = "header,compensation=on"
BODY = [
    "env,0.0,20.4,100800,42.0,20.9",
    "0.5,0.0,0.0",
    "1.0,100.0,1.25",
    "1.5,200.0,2.5",
    "env,2.0,20.6,100810,42.5,21.0",
    "2.5,300.0,3.75",
]

SCENARIOS = {
    # Lines 1-8, then end (line 9).
    "good": ["# test peer: compensation off", HEADER_OFF] + BODY + ["end"],
    "compensated": ["# test peer: compensation on", HEADER_ON] + BODY + ["end"],
    # Line 7: pressure in hPa. Three readings (lines 4-6) come before it.
    "bad-line": ["# test peer: a bad line", HEADER_OFF] + BODY[:4]
                + ["env,2.0,20.6,1008.1,42.5,21.0", "2.5,300.0,3.75", "end"],
}


def payload(scenario):
    if scenario == "close-mid":
        # Two readings, then the connection drops in the middle of a line.
        lines = ["# test peer: closes mid-stream", HEADER_OFF] + BODY[:3]
        return ("\r\n".join(lines) + "\r\n1.5,200.").encode()
    return ("\n".join(SCENARIOS[scenario]) + "\n").encode()


def send_chunked(conn, data):
    for i in range(0, len(data), 7):
        conn.sendall(data[i:i + 7])
        time.sleep(0.001)


def accept(server):
    conn, _ = server.accept()
    conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return conn


def serve_plan(server, readings, drop_after):
    """The readings at their times, over one connection or two (--drop-after)."""
    start = time.monotonic()
    clock = lambda: time.monotonic() - start

    def begin(conn):
        now = clock()
        send_chunked(conn, ("header,compensation=off,reference=standard-air\n"
                            "env,%.3f,20.0,101325,50.0\n" % now).encode())
        return now

    conn = accept(server)
    last_env = begin(conn)
    for k, (send_at, position, deviation) in enumerate(readings):
        if drop_after is not None and k == drop_after:
            conn.sendall(b"%.3f,12.3" % clock())  # cut off mid-line
            conn.close()
            conn = accept(server)
            last_env = begin(conn)
        time.sleep(max(0.0, send_at - clock()))
        now = max(clock(), last_env)
        send_chunked(conn, ("%.3f,%.6f,%.4f\n" % (now, position, deviation)).encode())
    # The reader logs the rest of its run; the stream stays alive until it leaves.
    try:
        for _ in range(600):
            time.sleep(1.0)
            send_chunked(conn, ("env,%.3f,20.0,101325,50.0\n" % clock()).encode())
    except OSError:
        pass
    conn.close()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scenario", default="good",
                        choices=sorted(SCENARIOS) + ["close-mid", "plan"])
    parser.add_argument("--port", type=int, default=0)
    parser.add_argument("--readings", help="plan: send_at_s,position_mm,deviation_um lines")
    parser.add_argument("--drop-after", type=int, default=None)
    args = parser.parse_args()

    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", args.port))
    server.listen(1)
    server.settimeout(60)  # a test that never connects must not leave us behind
    print(server.getsockname()[1], flush=True)
    if args.scenario == "plan":
        with open(args.readings) as f:
            readings = [tuple(float(x) for x in line.split(","))
                        for line in f if line.strip()]
        serve_plan(server, readings, args.drop_after)
    else:
        with accept(server) as conn:
            send_chunked(conn, payload(args.scenario))
    server.close()


if __name__ == "__main__":
    main()
