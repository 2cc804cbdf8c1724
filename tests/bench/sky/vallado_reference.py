#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Vallado's C++ SGP4, timed the way bench_sky times Slew's.

The reference for Slew's SGP4 figures: the same real sets (tests/data), the
same grids of times about each set's epoch, in order (COUNT:HALF_SPAN:
COUNT times from -HALF_SPAN to just short of +HALF_SPAN minutes; bench_sky
passes its own), near-earth and deep-space apart, states per CPU-second of
this thread. python3-sgp4 runs Vallado's C++ when it was built with its
extension (`accelerated`); the loop over the times then runs in C++
(Satrec.sgp4_array), and Vallado's integrator carries its resonance state
from one time to the next as it does in any caller. Each set gets as many
rounds of the grid in a row as make 2000 states, then the next set, as in
bench_sky; each call is given 2000 times (a long grid in pieces: the
integrator's state is the Satrec's, so it goes on across calls). That
spreads Python's cost per call (a few microseconds) thin, and keeps the
output arrays as small for one grid as for the other.

A pure-Python python3-sgp4 (Debian 12's is: its package has no extension)
would time Python, not Vallado's C++, so this says so and measures nothing.

    /usr/bin/python3 tests/bench/sky/vallado_reference.py [TLE-FILE [COUNT:HALF_SPAN ...]]
"""

import os
import sys
import time

DEFAULT_GRIDS = ['200:1440', '10000:14400']   # as bench_sky: +-1 day, +-10 days
STATES_PER_CALL = 2000
MEASURE_SECONDS = 1.5    # as bench_sky


def read_sets(path):
    """(line1, line2) of every set in a 2- or 3-line file."""
    with open(path, encoding='latin-1') as f:
        lines = [line.rstrip('\r\n') for line in f]
    return [(a, b) for a, b in zip(lines, lines[1:]) if a.startswith('1 ') and b.startswith('2 ')]


def grid_minutes(spec):
    """The minutes from epoch of a COUNT:HALF_SPAN grid, as bench_sky's TimeGrid::at."""
    import numpy as np
    count, half_span = spec.split(':')
    count, half_span = int(count), float(half_span)
    return -half_span + np.arange(count) * (2.0 * half_span / count)


def states_per_second(satellites, minutes):
    """States per CPU-second over the satellites, each at its own epoch + minutes."""
    import numpy as np
    if not satellites:
        return 0.0
    rounds = max(1, STATES_PER_CALL // len(minutes))
    calls = []
    for s in satellites:
        fr = np.tile(s.jdsatepochF + minutes / 1440.0, rounds)
        jd = np.full(fr.shape, s.jdsatepoch)
        for start in range(0, len(fr), STATES_PER_CALL):
            calls.append((s, jd[start:start + STATES_PER_CALL], fr[start:start + STATES_PER_CALL]))
    states = 0
    wall_start = time.perf_counter()
    cpu_start = time.thread_time()
    while time.perf_counter() - wall_start < MEASURE_SECONDS:
        for s, jd, fr in calls:
            s.sgp4_array(jd, fr)
            states += len(fr)
            if time.perf_counter() - wall_start >= MEASURE_SECONDS:
                break
    return states / (time.thread_time() - cpu_start)


def package_version():
    import sgp4
    if hasattr(sgp4, '__version__'):
        return sgp4.__version__
    from importlib import metadata
    try:
        return metadata.version('sgp4')
    except metadata.PackageNotFoundError:
        return '(version unknown)'


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, '..', '..', 'data',
                                                              'gpredict-satellites-2018.tle')
    grids = sys.argv[2:] or DEFAULT_GRIDS
    try:
        import numpy  # noqa: F401 (sgp4_array takes and gives its arrays)
        from sgp4.api import Satrec, accelerated
    except ImportError as e:
        print('Vallado reference: not measured (%s: install python3-sgp4 and python3-numpy)' % e)
        return 2
    version = package_version()
    if not accelerated:
        print('Vallado reference: not measured (python3-sgp4 %s here is its pure-Python fallback, '
              'without Vallado\'s C++)' % version)
        return 2

    near, deep = [], []
    for line1, line2 in read_sets(path):
        s = Satrec.twoline2rv(line1, line2)
        # As bench_sky: a set already failing at epoch is left out.
        error, _, _ = s.sgp4(s.jdsatepoch, s.jdsatepochF)
        if error != 0:
            continue
        (deep if s.method == 'd' else near).append(s)

    for spec in grids:
        minutes = grid_minutes(spec)
        days = -minutes[0] / 1440.0
        label = '%d times over +-%g %s' % (len(minutes), days, 'day' if days == 1.0 else 'days')
        print('Vallado C++ (python3-sgp4 %s) near-earth, %s: %.3g states/s (%d sets)'
              % (version, label, states_per_second(near, minutes), len(near)))
        print('Vallado C++ (python3-sgp4 %s) deep-space, %s: %.3g states/s (%d sets)'
              % (version, label, states_per_second(deep, minutes), len(deep)))
        sys.stdout.flush()
    return 0


if __name__ == '__main__':
    sys.exit(main())
