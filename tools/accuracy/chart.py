#!/usr/bin/python3
"""Speed against accuracy: log-log charts of cost against error from proceduray_accuracy and
proceduray_sweep CSVs.

    tools/accuracy/chart.py sweep.csv --out mandelbulb.png --object mandelbulb
    tools/accuracy/chart.py a.csv b.csv --out paper.png            # every object, one panel each
    tools/accuracy/chart.py sweep.csv --cost trace_ms --out time.png
    tools/accuracy/chart.py sweep.csv --error silhouette --out fat.png   # silhouette false hits

Each CSV row group (one run of the tool: its knob columns) gives one point per object: x is the
cost (evaluations per ray that sees the object, `object_evals`, or the frame's `trace_ms`), y the
depth error in pixel footprints (median as dots, p99 as crosses). The Pareto front of the
medians (no other run is both cheaper and more accurate) is drawn as a line, and every point is
labelled with its knobs, so the cheapest setting that meets an error can be read off the chart.
--error silhouette charts the false-hit rate of the 1-pixel silhouette band instead (percent of
its rays that hit where the truth misses: fat silhouettes), on a linear axis.
Needs matplotlib (Debian: python3-matplotlib, installed by tools/setup.sh); --front prints the
fronts as text without it. Exit status 2 with a message on bad input (unknown object or cost
column, a CSV without the tool's header).
"""
import argparse
import csv
import math
import sys

KNOBS = ('max_steps', 'threshold_px', 'epsilon', 'step_scale')
COSTS = ('object_evals', 'trace_ms', 'steps_mean', 'evals_per_hit', 'evals_per_near_miss')


def fail(message):
    print(f'chart.py: {message}', file=sys.stderr)
    sys.exit(2)


def label(row):
    """The knobs of a run, short: '256 st, 0.5 px' (accuracy tool) or 'relaxed w1.5 0.5px' (sweep)."""
    if 'method' not in row:
        return f"{int(float(row['max_steps']))} st, {float(row['threshold_px']):.3g} px"
    if row.get('label') == 'd3d12 sample':
        return 'D3D12 sample'
    parts = [row['method']]
    if row['method'] == 'relaxed':
        parts.append(f"w{float(row['relaxation']):g}")
    if row['method'] == 'fixed':
        parts.append(f"n{row['fixed_steps']}")
    unit = 'px' if row['threshold_mode'] == 'footprint' else 'u'
    parts.append(f"{float(row['threshold']):g}{unit}")
    if row['refine'] == 'off':
        parts.append('unrefined')
    if row['normal'] == 'tetrahedral':
        parts.append('tetra')
    if row.get('iteration_mode') == 'by_distance':
        parts.append('iter/dist')
    elif 'iterations' in (row.get('label') or ''):
        parts.append(f"it{row['iterations']}")
    if 'max_steps' in (row.get('label') or ''):
        parts.append(f"{row['max_steps']}st")
    return ' '.join(parts)


def points(paths, cost, objects, error='depth'):
    """{object: [(cost, median, p99, label)]} from the rows of class 'all'; with error 'silhouette',
    (cost, false-hit percent, None, label) from the rows of class silhouette_1px."""
    out = {}
    for path in paths:
        try:
            with open(path, newline='') as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            fail(f'cannot read {path}: {e.strerror}; pass a CSV written by proceduray_accuracy --csv')
        if not rows or 'object' not in rows[0] or 'depth_px_median' not in rows[0]:
            fail(f'{path} has no proceduray_accuracy header (object, depth_px_median); pass a CSV the tool wrote')
        if cost not in rows[0]:
            fail(f"{path} has no column '{cost}'; pass --cost one of {', '.join(c for c in COSTS if c in rows[0])}")
        for row in rows:
            if error == 'silhouette':
                if row['class'] != 'silhouette_1px' or not row.get('false_hit_rate') or not row[cost]:
                    continue
                x, rate = float(row[cost]), 100.0 * float(row['false_hit_rate'])
                if math.isfinite(x) and x > 0 and math.isfinite(rate):
                    out.setdefault(row['object'], []).append((x, rate, None, label(row)))
                continue
            if row['class'] != 'all':
                continue
            if not (row[cost] and row['depth_px_median'] and row['depth_px_p99']):
                continue  # no hits: the field is empty ("no data")
            x, median, p99 = float(row[cost]), float(row['depth_px_median']), float(row['depth_px_p99'])
            if not all(math.isfinite(v) and v > 0 for v in (x, median, p99)):
                continue  # no hits of this object in that run, or an exact zero: nothing to place on a log axis
            out.setdefault(row['object'], []).append((x, median, p99, label(row)))
    if objects:
        missing = [o for o in objects if o not in out]
        if missing:
            fail(f"no measured hits of {', '.join(missing)}; objects with hits: {', '.join(sorted(out)) or 'none'}")
        out = {o: out[o] for o in objects}
    if not out:
        fail('no rows with hits; run proceduray_accuracy --csv first')
    return out


def pareto_front(pts):
    """The points no other point beats in both cost and error (ties kept once), cheapest first."""
    front = []
    for x, y, *rest in sorted(pts, key=lambda p: (p[0], p[1])):
        if not front or y < front[-1][1]:
            front.append((x, y, *rest))
    return front


def main(argv=None):
    p = argparse.ArgumentParser(description='Log-log cost against depth error, Pareto front marked.')
    p.add_argument('csv', nargs='+', help='CSVs written by proceduray_accuracy --csv (--append for sweeps)')
    p.add_argument('--out', help='PNG to write (needs matplotlib)')
    p.add_argument('--object', action='append', default=[], help='object to chart (repeat); default every one')
    p.add_argument('--cost', default='object_evals', help=f"x axis: one of {', '.join(COSTS)}")
    p.add_argument('--error', default='depth', help='y axis: depth (median and p99, footprints) or silhouette '
                   '(false hits in the 1-pixel band, percent)')
    p.add_argument('--front', action='store_true', help='print each object\'s Pareto front as text')
    a = p.parse_args(argv)
    if a.error not in ('depth', 'silhouette'):
        fail(f"unknown error '{a.error}'; pass depth or silhouette")
    if a.cost not in COSTS:
        fail(f"unknown cost '{a.cost}'; pass one of {', '.join(COSTS)}")
    if not a.out and not a.front:
        fail('nothing to do; pass --out PNG or --front')
    data = points(a.csv, a.cost, a.object, a.error)
    if a.front:
        for obj, pts in sorted(data.items()):
            print(obj + ': ' + '; '.join(f'{lab}: {x:.3g} {a.cost}, median {y:.3g} px'
                                          for x, y, _, lab in pareto_front([(x, m, q, lab) for x, m, q, lab in pts])))
    if not a.out:
        return 0
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FuncFormatter
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    names = sorted(data)
    cols = min(3, len(names))
    rows = (len(names) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.2 * rows), squeeze=False)
    for ax, obj in zip(axes.flat, names):
        pts = data[obj]
        xs = [q[0] for q in pts]
        ax.scatter(xs, [q[1] for q in pts], color='tab:blue', label='median' if a.error == 'depth' else 'false hits',
                   zorder=3)
        if a.error == 'depth':
            ax.scatter(xs, [q[2] for q in pts], color='tab:red', marker='x', label='p99', zorder=3)
        front = pareto_front([(x, m, lab) for x, m, _, lab in pts])
        ax.plot([q[0] for q in front], [q[1] for q in front], color='tab:blue', alpha=0.5,
                label='front (median)' if a.error == 'depth' else 'front')
        # A big sweep labels its front and the D3D12 sample's settings only (the rest would be unreadable).
        named = pts if len(pts) <= 12 else [q for q in pts if q[3] == 'D3D12 sample' or
                                             any(q[0] == f[0] and q[1] == f[1] for f in front)]
        for x, m, _, lab in named:
            ax.annotate(lab, (x, m), textcoords='offset points', xytext=(4, 4), fontsize=7)
        ax.set_xscale('log')
        ax.set_yscale('log' if a.error == 'depth' else 'linear')
        short = FuncFormatter(lambda v, _: f'{v:g}')  # '40', not '4 x 10^1': a sweep spans under a decade
        ax.xaxis.set_major_formatter(short)
        ax.xaxis.set_minor_formatter(short)
        ax.set_title(obj)
        ax.set_xlabel('evaluations per ray' if a.cost == 'object_evals' else a.cost)
        ax.set_ylabel('depth error, pixel footprints' if a.error == 'depth' else 'silhouette false hits, %')
        ax.grid(True, which='both', alpha=0.3)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(names):]:
        ax.axis('off')
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)
    print(f'wrote {a.out}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
