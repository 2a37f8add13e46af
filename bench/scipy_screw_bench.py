#!/usr/bin/env python3
"""The 8-hour / 200-cell screw campaign of simulation_bench, in numpy + scipy.

The same physics as core/physics (backward Euler, finite volumes, convection
h·P·(T − T_amb), the nut deposited exactly with the ramp antiderivative,
bearing heat c_b·|ω| into both end cells, insulated ends) and the same
campaign as BenchmarkCampaign: reciprocating 210–490 mm at 8000 mm/min in
10 min blocks with 100 s dwells, 1 s steps, room 20 → 22 °C. Each step solves
the tridiagonal system with scipy.linalg.solve_banded, the idiomatic way.

Prints one JSON object: cell_steps_per_s and campaign_ms (medians), and the
free-end thermal error, which must agree with the C++ model's to ~1e-9.

Exit codes: 0 done, 2 numpy or scipy missing.
"""

import argparse
import json
import math
import statistics
import sys
import time

try:
    import numpy as np
    from scipy.linalg import solve_banded
except ImportError as error:  # pragma: no cover - depends on the machine
    print(f"scipy_screw_bench: needs numpy and scipy ({error}); "
          "install python3-scipy", file=sys.stderr)
    sys.exit(2)

# ScrewThermalParameters defaults (SI); keep in step with core/physics/ScrewThermalParameters.h
LENGTH, DIAMETER, LEAD, NUT = 0.9, 0.04, 0.01, 0.08
FIXED_END_AXIS_MM = -40.0
RHO, CP, K, ALPHA = 7850.0, 460.0, 45.0, 11.5e-6
C_NUT, C_BEARING, H = 0.11, 0.02, 12.0
CELLS, DT, DURATION = 200, 1.0, 8 * 3600.0


def campaign_motion():
    """(start_s, end_s, from_mm, to_mm) segments, as BenchmarkCampaign builds them."""
    lo, hi, feed, block, dwell = 210.0, 490.0, 8000.0, 600.0, 100.0
    motion, t, at, up = [], 0.0, lo, True
    while t < DURATION:
        block_end = min(DURATION, t + block)
        while t < block_end:
            target = hi if up else lo
            full = abs(target - at) / feed * 60
            if t + full <= block_end:
                motion.append((t, t + full, at, target))
                t, at, up = t + full, target, not up
            else:
                reached = at + (target - at) * (block_end - t) / full
                motion.append((t, block_end, at, reached))
                t, at = block_end, reached
        pause = min(dwell, DURATION - t)
        if pause <= 0:
            break
        motion.append((t, t + pause, at, at))
        t += pause
    return motion


def ramp(u):
    return np.where(u > 0, 0.5 * u * u, 0.0)


def simulate(motion):
    dx = LENGTH / CELLS
    area = math.pi * DIAMETER ** 2 / 4
    cap = RHO * CP * area * dx
    g = K * area / dx
    hs = H * math.pi * DIAMETER * dx
    diag = np.full(CELLS, cap / DT + hs + 2 * g)
    diag[0] -= g
    diag[-1] -= g
    ab = np.zeros((3, CELLS))
    ab[0, 1:] = -g
    ab[1] = diag
    ab[2, :-1] = -g
    faces = np.arange(CELLS + 1) * dx
    half = NUT / 2

    temperature = np.full(CELLS, 20.0)
    source = np.zeros(CELLS)
    steps = int(DURATION / DT)
    cursor = 0
    for i in range(steps):
        t0, t1 = i * DT, (i + 1) * DT
        source[:] = 0
        while cursor < len(motion) and motion[cursor][1] <= t0:
            cursor += 1
        k = cursor
        while k < len(motion) and motion[k][0] < t1:
            s0, s1, f_mm, t_mm = motion[k]
            k += 1
            a, b = max(s0, t0), min(s1, t1)
            if b <= a or f_mm == t_mm:
                continue
            at = lambda t: (f_mm + (t_mm - f_mm) * (t - s0) / (s1 - s0) - FIXED_END_AXIS_MM) * 1e-3
            x0, x1 = at(a), at(b)
            lo, hi = min(x0, x1), max(x0, x1)
            omega = 2 * math.pi * abs(x1 - x0) / (b - a) / LEAD
            power = C_NUT * omega
            anti = (ramp(faces + half - lo) - ramp(faces + half - hi)
                    - ramp(faces - half - lo) + ramp(faces - half - hi))
            source += power * (b - a) / (NUT * (hi - lo)) * np.diff(anti)
            bearing = C_BEARING * omega * (b - a)
            source[0] += bearing
            source[-1] += bearing
        ambient_end = 20 + 2 * (i + 1) / steps
        rhs = cap / DT * temperature + hs * ambient_end + source / DT
        temperature = solve_banded((1, 1), ab, rhs, check_finite=False)
    return ALPHA * dx * float(np.sum(temperature - 20.0)) * 1e6


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="campaigns to time (median)")
    args = parser.parse_args()
    motion = campaign_motion()
    times, error_um = [], 0.0
    for _ in range(max(1, args.repeat)):
        start = time.perf_counter()
        error_um = simulate(motion)
        times.append(time.perf_counter() - start)
    seconds = statistics.median(times)
    cell_steps = CELLS * int(DURATION / DT)
    print(json.dumps({
        "cell_steps_per_s": cell_steps / seconds,
        "campaign_ms": seconds * 1e3,
        "repetitions": len(times),
        "cells": CELLS,
        "steps": int(DURATION / DT),
        "free_end_error_um": error_um,
    }))
    return 0


if __name__ == "__main__":
    sys.exit(main())
