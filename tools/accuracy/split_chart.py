#!/usr/bin/python3
"""Where the evaluations go, per object: the evaluations per ray of the rays that hit it, of those
that miss it within 2 pixels of its silhouette, and (for the whole frame) of the far misses, from
the CSV that proceduray_accuracy --split-csv writes. A panel per object; each bar is labelled with
its rays and its share of the frame's evaluations.

    proceduray_accuracy --scene paper --size 1920x1080 --stride 8 --split-csv split.csv
    tools/accuracy/split_chart.py split.csv --out split.png --objects mandelbulb julia

Needs matplotlib (Debian: python3-matplotlib). Exit status 2 with a message on bad input
(unreadable file, missing columns, an unknown class, negative or non-numeric values, an object
the file lacks).
"""
import argparse
import csv
import math
import sys

COLUMNS = ('object', 'class', 'rays', 'evaluations', 'evals_per_ray', 'share')
CLASSES = (('hit', 'hits', '#3b7dd8'), ('near_miss', 'near misses', '#e8853a'), ('far_miss', 'far misses', '#8a8a8a'))


def fail(message):
    print(f'split_chart.py: {message}', file=sys.stderr)
    sys.exit(2)


def read(path):
    """{object: {class: (rays, evals_per_ray, share)}}, objects in file order."""
    hint = 'pass a CSV written by proceduray_accuracy --split-csv'
    try:
        with open(path, newline='') as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}; {hint}')
    if not rows or any(c not in rows[0] for c in COLUMNS):
        fail(f'{path} has no rows or lacks a column of {", ".join(COLUMNS)}; {hint}')
    out = {}
    for n, r in enumerate(rows, start=2):
        if r['class'] not in (c[0] for c in CLASSES):
            fail(f'{path} line {n}: class {r["class"]!r} is not hit, near_miss or far_miss')
        try:
            values = tuple(float(r[c]) for c in ('rays', 'evals_per_ray', 'share'))
        except (TypeError, ValueError):
            fail(f'{path} line {n}: a value that is not a number; {hint}')
        if any(not math.isfinite(v) or v < 0 for v in values):
            fail(f'{path} line {n}: a negative or non-finite value')
        out.setdefault(r['object'], {})[r['class']] = values
    return out


def main(argv=None):
    p = argparse.ArgumentParser(description='Evaluations per ray by ray class, a panel per object.')
    p.add_argument('csv', help='a CSV written by proceduray_accuracy --split-csv')
    p.add_argument('--out', required=True, help='PNG to write')
    p.add_argument('--objects', nargs='+', help='objects to draw (default: every object in the file)')
    p.add_argument('--title', default='evaluations per ray, by ray class', help='chart title')
    a = p.parse_args(argv)
    data = read(a.csv)
    names = a.objects or list(data)
    for n in names:
        if n not in data:
            fail(f'{a.csv} has no object {n!r}; it has {", ".join(data)}')
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    columns = min(4, len(names))  # rows of at most 4 panels
    rows = (len(names) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(3.2 * columns + 1.0, 3.4 * rows + 0.4), squeeze=False,
                             sharey=True)  # one scale: objects compare at a glance
    panels = [ax for row in axes for ax in row]
    for ax in panels[len(names):]:
        ax.set_visible(False)
    for ax, name in zip(panels, names):
        classes = [c for c in CLASSES if c[0] in data[name]]
        heights = [data[name][c[0]][1] for c in classes]
        bars = ax.bar([c[1] for c in classes], heights, color=[c[2] for c in classes])
        for bar, c in zip(bars, classes):
            rays, _, share = data[name][c[0]]
            ax.annotate(f'{rays:.0f} rays\n{100 * share:.1f}%', (bar.get_x() + bar.get_width() / 2, bar.get_height()),
                        ha='center', va='bottom', fontsize=8)
        ax.set_title(name)
        ax.tick_params(axis='x', labelsize=8)
    top = max(v[1] for n in names for v in data[n].values())
    axes[0][0].set_ylim(0, 1.25 * max(top, 1.0))
    for row in axes:
        row[0].set_ylabel('evaluations per ray')
    fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)
    print(f'wrote {a.out}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
