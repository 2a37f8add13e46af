#!/usr/bin/python3
"""A laser interferometer streaming DriftLab's line protocol
(docs/interferometer.md), written from the document, stdlib only.

    python3 interferometer_stream.py --scenario good|bad-line|close-mid|compensated

Listens on 127.0.0.1 at a free port (bound to port 0), prints the port as its
first line, serves one connection and exits. The bytes go out in small chunks
that cut lines in the middle, as a real serial-to-TCP bridge does.
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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scenario", default="good",
                        choices=sorted(SCENARIOS) + ["close-mid"])
    args = parser.parse_args()
    data = payload(args.scenario)

    server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    server.bind(("127.0.0.1", 0))
    server.listen(1)
    server.settimeout(60)  # a test that never connects must not leave us behind
    print(server.getsockname()[1], flush=True)
    conn, _ = server.accept()
    with conn:
        conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        for i in range(0, len(data), 7):
            conn.sendall(data[i:i + 7])
            time.sleep(0.001)
    server.close()


if __name__ == "__main__":
    main()
