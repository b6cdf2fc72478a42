#!/usr/bin/python3
"""Where a march spends its evaluations: a heat map of the per-pixel step counts that
proceduray_accuracy --steps-csv writes (a row per image row, a value per pixel).

    proceduray_accuracy --scene paper --size 320x240 --steps-csv steps.csv
    tools/accuracy/heatmap.py steps.csv --out heat.png --title "paper scene, default knobs"

Colours are evaluations per camera ray (0, black: no marched primitive on the ray), on a
logarithmic scale, with a colour bar; the title gets the mean and the maximum. Needs matplotlib
(Debian: python3-matplotlib). Exit status 2 with a message on bad input (unreadable file, ragged
or non-numeric rows, negative counts).
"""
import argparse
import csv
import sys


def fail(message):
    print(f'heatmap.py: {message}', file=sys.stderr)
    sys.exit(2)


def read(path):
    """The rows of counts; every row as long as the first."""
    try:
        with open(path, newline='') as f:
            rows = [[float(v) for v in row] for row in csv.reader(f) if row]
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}; pass a CSV written by proceduray_accuracy --steps-csv')
    except ValueError:
        fail(f'{path} has a value that is not a number; pass a CSV written by proceduray_accuracy --steps-csv')
    if not rows or any(len(r) != len(rows[0]) for r in rows):
        fail(f'{path} is empty or its rows differ in length; pass a CSV written by proceduray_accuracy --steps-csv')
    if any(v < 0 for r in rows for v in r):
        fail(f'{path} has a negative count')
    return rows


def main(argv=None):
    p = argparse.ArgumentParser(description='Heat map of per-pixel evaluation counts.')
    p.add_argument('csv', help='a CSV written by proceduray_accuracy --steps-csv')
    p.add_argument('--out', required=True, help='PNG to write')
    p.add_argument('--title', default='evaluations per camera ray', help='chart title')
    a = p.parse_args(argv)
    rows = read(a.csv)
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        from matplotlib.colors import LogNorm
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    values = [v for r in rows for v in r]
    marched = [v for v in values if v > 0]
    h, w = len(rows), len(rows[0])
    fig, ax = plt.subplots(figsize=(min(12.0, 2.0 + w / 40.0), min(9.0, 1.0 + h / 40.0)))
    ax.set_facecolor('black')
    masked = [[v if v > 0 else float('nan') for v in r] for r in rows]
    image = ax.imshow(masked, cmap='inferno', norm=LogNorm(vmin=max(1.0, min(marched, default=1.0)),
                                                           vmax=max(2.0, max(marched, default=2.0))),
                      interpolation='nearest')
    fig.colorbar(image, ax=ax, label='evaluations')
    mean = sum(marched) / len(marched) if marched else 0.0
    ax.set_title(f'{a.title}\nmean {mean:.1f} over {len(marched)} marched rays, max {max(values):.0f}')
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(a.out, dpi=90)
    print(f'wrote {a.out}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
