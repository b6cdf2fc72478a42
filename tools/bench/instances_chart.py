#!/usr/bin/python3
"""Frame time against the number of marched instances, the library's ray-tracing pipeline beside
the compute peer that tests every instance per ray, on log-log axes, from the CSV bench_instances
writes (one file per device, or several: a line pair per device). Where the peer's line crosses
above the library's, the pipeline's acceleration structure pays for itself.

    bench_instances --device cpu --csv lavapipe.csv
    tools/bench/instances_chart.py lavapipe.csv h200.csv --out instances.png

Needs matplotlib (Debian: python3-matplotlib). Exit status 2 with a message on bad input
(unreadable file, missing columns, non-numeric, non-positive or non-finite times or counts).
"""
import argparse
import csv
import math
import sys

COLUMNS = ('device', 'instances', 'library_ms', 'peer_ms')


def fail(message):
    print(f'instances_chart.py: {message}', file=sys.stderr)
    sys.exit(2)


def read(path):
    """{device: [(instances, library_ms, peer_ms)]}, sorted by instances."""
    hint = 'pass a CSV written by bench_instances --csv'
    try:
        with open(path, newline='') as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}; {hint}')
    if not rows or any(c not in rows[0] for c in COLUMNS):
        fail(f'{path} has no rows or lacks a column of {", ".join(COLUMNS)}; {hint}')
    out = {}
    for n, r in enumerate(rows, start=2):
        try:
            values = (float(r['instances']), float(r['library_ms']), float(r['peer_ms']))
        except (TypeError, ValueError):
            fail(f'{path} line {n}: a value that is not a number; {hint}')
        if any(not math.isfinite(v) or v <= 0 for v in values):
            fail(f'{path} line {n}: a count or time that is not positive and finite')
        out.setdefault(r['device'], []).append(values)
    return {d: sorted(v) for d, v in out.items()}


def main(argv=None):
    p = argparse.ArgumentParser(description='Frame time against marched instances: library and compute peer.')
    p.add_argument('csv', nargs='+', help='CSVs written by bench_instances --csv')
    p.add_argument('--out', required=True, help='PNG to write')
    p.add_argument('--title', default='camera rays through n Mandelbulbs', help='chart title')
    a = p.parse_args(argv)
    data = {}
    for path in a.csv:
        data.update(read(path))
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    colours = ['#3b7dd8', '#2a9d55', '#8e44ad', '#c0392b']
    for i, (device, rows) in enumerate(data.items()):
        c = colours[i % len(colours)]
        n = [r[0] for r in rows]
        ax.plot(n, [r[1] for r in rows], '-o', color=c, label=f'library (pipeline): {device}')
        ax.plot(n, [r[2] for r in rows], '--s', color='#e8853a' if len(data) == 1 else c, label=f'compute peer: {device}')
    ax.set_xscale('log')
    ax.set_yscale('log')
    ax.set_xlabel('marched instances')
    ax.set_ylabel('trace time per frame (ms, median)')
    ax.set_title(a.title)
    ax.grid(True, which='both', alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    try:
        fig.savefig(a.out, dpi=110)
    except OSError as e:
        fail(f'cannot write {a.out}: {e.strerror}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
