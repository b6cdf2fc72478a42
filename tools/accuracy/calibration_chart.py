#!/usr/bin/python3
"""A calibration table as a chart: cost against every error, one panel per error, each setting
a point, the settings that meet the budget filled and the cheapest of them (the pick) ringed.

    tools/accuracy/calibration_chart.py gyroid.png.csv --out gyroid_chart.png
    tools/accuracy/calibration_chart.py table.csv --geometry gyroid --median 0.25 --out chart.png
    tools/accuracy/calibration_chart.py table.csv --pick           # the pick as text, no matplotlib

The table is what proceduray::vk::calibrate keeps (march/calibration.hpp's CSV: three # lines,
then a header and a row per setting). The budget defaults to ErrorBudget's: depth median 0.1 and
p99 2 footprints, silhouette false hits, false misses and wrong-surface 0.5%; a flag relaxes
one. Errors of 0 are drawn at 1e-6 (log axes). A setting meets it only if every error does, so the front is over every error, not the
median alone. Needs matplotlib (Debian: python3-matplotlib) except with --pick. Exit status 2
with a message on bad input (not a calibration table, an unknown geometry).
"""
import argparse
import csv
import math
import sys

ERRORS = (('depth_median', 'depth median (footprints)', 'median'), ('depth_p99', 'depth p99 (footprints)', 'p99'),
          ('silhouette_false_hits', 'silhouette false hits', 'silhouette'),
          ('false_misses', 'false misses', 'misses'), ('wrong_surface', 'wrong surface', 'wrong_surface'))


def fail(message):
    print(f'calibration_chart.py: {message}', file=sys.stderr)
    sys.exit(2)


def read(path):
    try:
        with open(path, newline='') as f:
            lines = f.read().splitlines()
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}')
    if not lines or not lines[0].startswith('# proceduray-calibration'):
        fail(f'{path} is not a calibration table (line 1 is not "# proceduray-calibration N")')
    return list(csv.DictReader(line for line in lines if not line.startswith('#')))


def number(row, key):
    value = row.get(key, '')
    try:
        return float(value)
    except ValueError:
        return math.nan  # unmeasured (a format-1 table): meets no bound below 1


def label(row):
    parts = [row['method']]
    if row['method'] == 'relaxed':
        parts.append(f"w{float(row['relaxation']):g}")
    if row['method'] == 'fixed':
        parts.append(f"n{row['fixed_steps']}")
    parts.append(f"{float(row['threshold']):g}{'px' if row['threshold_mode'] == 'footprint' else 'u'}")
    if row.get('iterations', '0') not in ('0', ''):
        parts.append(f"it{row['iterations']}")
    return ' '.join(parts)


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('table')
    p.add_argument('--geometry', help='the geometry to chart (default: the first in the table)')
    p.add_argument('--out', default='calibration.png')
    p.add_argument('--pick', action='store_true', help='print the pick and exit')
    bounds = {'median': 0.1, 'p99': 2.0, 'silhouette': 0.005, 'misses': 0.005, 'wrong_surface': 0.005}
    for name, value in bounds.items():
        p.add_argument(f'--{name.replace("_", "-")}', type=float, default=value, dest=name)
    a = p.parse_args()
    rows = read(a.table)
    if not rows:
        fail(f'{a.table} has no rows')
    geometry = a.geometry or rows[0]['geometry']
    rows = [r for r in rows if r['geometry'] == geometry]
    if not rows:
        fail(f"no rows for '{geometry}'")
    budget = {key: getattr(a, arg) for key, _, arg in ERRORS}
    meets = [all(number(r, k) <= budget[k] or (budget[k] >= 1.0 and k != 'depth_median') for k, _, _ in ERRORS)
             for r in rows]
    ok = [r for r, m in zip(rows, meets) if m]
    pick = min(ok, key=lambda r: float(r['evals'])) if ok else None
    print(f"{geometry}: {len(ok)} of {len(rows)} settings meet the budget; pick: " +
          (f"{label(pick)} at {float(pick['evals']):.1f} evaluations" if pick else 'none'))
    if a.pick:
        return
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    except ImportError:
        fail('needs matplotlib (Debian: python3-matplotlib), or pass --pick')
    fig, axes = plt.subplots(1, len(ERRORS), figsize=(4 * len(ERRORS), 4))
    for ax, (key, title, _) in zip(axes, ERRORS):
        for r, m in zip(rows, meets):
            x, y = float(r['evals']), number(r, key)
            if not math.isfinite(y):
                continue
            ax.scatter([x], [max(y, 1e-6)], s=28, c='tab:blue' if m else 'white', edgecolors='tab:blue')
            if r is pick:
                ax.scatter([x], [max(y, 1e-6)], s=140, facecolors='none', edgecolors='tab:red')
        ax.axhline(budget[key], color='tab:red', lw=0.8, ls='--')
        ax.set_yscale('log')
        ax.set_xlabel('evaluations per ray')
        ax.set_title(title)
    fig.suptitle(f'{geometry}: filled = meets the budget, ringed = the pick' +
                 (f' ({label(pick)})' if pick else ' (none meets it)'))
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(f'wrote {a.out}')


if __name__ == '__main__':
    main()
