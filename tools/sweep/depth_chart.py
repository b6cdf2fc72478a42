#!/usr/bin/python3
"""Frame time against reflection depth, recursive and iterative tracing, from the CSV that
proceduray_reflection_depth --csv writes (mode, reflections, trace_ms_median, _min, _max).

    tools/sweep/depth_chart.py depth.csv --out docs/images/reflection_depth.png

One line per mode (medians, the min-max range shaded). Needs matplotlib (Debian:
python3-matplotlib). Exit status 2 with a message on bad input.
"""
import argparse
import csv
import sys


def fail(message):
    print(f'depth_chart.py: {message}', file=sys.stderr)
    sys.exit(2)


def series(path):
    """{mode: [(reflections, median, min, max)]}, sorted by reflections."""
    try:
        with open(path, newline='') as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}; pass a CSV written by proceduray_reflection_depth --csv')
    need = ('mode', 'reflections', 'trace_ms_median', 'trace_ms_min', 'trace_ms_max')
    if not rows or any(k not in rows[0] for k in need):
        fail(f"{path} lacks the columns {', '.join(need)}; pass a CSV written by proceduray_reflection_depth --csv")
    out = {}
    for r in rows:
        try:
            out.setdefault(r['mode'], []).append((int(r['reflections']), float(r['trace_ms_median']),
                                                  float(r['trace_ms_min']), float(r['trace_ms_max'])))
        except ValueError:
            fail(f'{path} has a value that is not a number in row {r}')
    return {m: sorted(v) for m, v in out.items()}, rows[0].get('device', ''), rows[0].get('width', ''), rows[0].get('height', '')


def main(argv=None):
    p = argparse.ArgumentParser(description='Frame time against reflection depth.')
    p.add_argument('csv')
    p.add_argument('--out', required=True, help='PNG to write')
    a = p.parse_args(argv)
    data, device, w, h = series(a.csv)
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    colours = {'recursive': 'tab:red', 'iterative': 'tab:blue'}
    for mode, pts in sorted(data.items()):
        xs = [q[0] for q in pts]
        ax.plot(xs, [q[1] for q in pts], marker='o', color=colours.get(mode, None), label=mode)
        ax.fill_between(xs, [q[2] for q in pts], [q[3] for q in pts], color=colours.get(mode, None), alpha=0.2)
    ax.set_xlabel('reflections traced (max depth - 1)')
    ax.set_ylabel('trace time, ms (GPU timestamps, median)')
    ax.set_title(f'reflection depth: {device} {w}x{h}'.strip())
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)
    print(f'wrote {a.out}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
