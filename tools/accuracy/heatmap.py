#!/usr/bin/python3
"""Where a march spends its evaluations: a heat map of the per-pixel step counts that
proceduray_accuracy --steps-csv writes (a row per image row, a value per pixel).

    proceduray_accuracy --scene paper --size 320x240 --steps-csv steps.csv --classes-csv classes.csv
    tools/accuracy/heatmap.py steps.csv --out heat.png --title "paper scene, default knobs"
    tools/accuracy/heatmap.py steps.csv --classes classes.csv --out split.png   # a panel per ray class

Colours are evaluations per camera ray (0, black: no marched primitive on the ray), on a
logarithmic scale, with a colour bar; the title gets the mean and the maximum. With --classes
(the tool's --classes-csv: 1 hit, 2 near miss, 3 far miss, 0 unknown) the map is split into a
panel per class, each with its rays' mean, on one colour scale. Needs matplotlib
(Debian: python3-matplotlib). Exit status 2 with a message on bad input (unreadable file, ragged
or non-numeric rows, negative counts).
"""
import argparse
import csv
import sys


def fail(message):
    print(f'heatmap.py: {message}', file=sys.stderr)
    sys.exit(2)


CLASSES = ((1, 'hits'), (2, 'near misses'), (3, 'far misses'))


def read(path, option='--steps-csv'):
    """The rows of numbers; every row as long as the first."""
    try:
        with open(path, newline='') as f:
            rows = [[float(v) for v in row] for row in csv.reader(f) if row]
    except OSError as e:
        fail(f'cannot read {path}: {e.strerror}; pass a CSV written by proceduray_accuracy {option}')
    except ValueError:
        fail(f'{path} has a value that is not a number; pass a CSV written by proceduray_accuracy {option}')
    if not rows or any(len(r) != len(rows[0]) for r in rows):
        fail(f'{path} is empty or its rows differ in length; pass a CSV written by proceduray_accuracy {option}')
    if any(v < 0 for r in rows for v in r):
        fail(f'{path} has a negative count')
    return rows


def read_classes(path, shape):
    """The class grid of --classes: codes 0 to 3, the steps grid's shape."""
    rows = read(path, '--classes-csv')
    if (len(rows), len(rows[0])) != shape:
        fail(f'{path} is {len(rows[0])}x{len(rows)}, the steps grid {shape[1]}x{shape[0]}; '
             'pass both grids of one proceduray_accuracy run')
    if any(v not in (0, 1, 2, 3) for r in rows for v in r):
        fail(f'{path} has a class other than 0 (unknown), 1 (hit), 2 (near miss) or 3 (far miss)')
    return rows


def draw_split(plt, LogNorm, rows, classes, title):
    """A panel per ray class on one colour scale; each titled with its rays' mean evaluations."""
    marched = [v for r in rows for v in r if v > 0]
    # The scale starts below the least count, so that it is not drawn black (black: no march).
    norm = LogNorm(vmin=0.5 * max(1.0, min(marched, default=1.0)), vmax=max(2.0, max(marched, default=2.0)))
    h, w = len(rows), len(rows[0])
    fig, axes = plt.subplots(1, 3, figsize=(min(18.0, 7.5 + 3 * w / 80.0), min(7.0, 2.5 + h / 80.0)))
    for ax, (code, name) in zip(axes, CLASSES):
        mine = [[v if c == code and v > 0 else float('nan') for v, c in zip(r, cr)] for r, cr in zip(rows, classes)]
        values = [v for r, cr in zip(rows, classes) for v, c in zip(r, cr) if c == code]
        ax.set_facecolor('black')
        image = ax.imshow(mine, cmap='inferno', norm=norm, interpolation='nearest')
        mean = sum(values) / len(values) if values else 0.0
        ax.set_title(f'{name}\n{len(values)} rays, mean {mean:.1f}', fontsize=10)
        ax.set_xticks([])
        ax.set_yticks([])
    fig.colorbar(image, ax=list(axes), label='evaluations', shrink=0.8)
    fig.suptitle(title)
    return fig


def main(argv=None):
    p = argparse.ArgumentParser(description='Heat map of per-pixel evaluation counts.')
    p.add_argument('csv', help='a CSV written by proceduray_accuracy --steps-csv')
    p.add_argument('--out', required=True, help='PNG to write')
    p.add_argument('--title', default='evaluations per camera ray', help='chart title')
    p.add_argument('--classes', help='the per-pixel classes (proceduray_accuracy --classes-csv): a panel per class')
    a = p.parse_args(argv)
    rows = read(a.csv)
    classes = read_classes(a.classes, (len(rows), len(rows[0]))) if a.classes else None
    try:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        from matplotlib.colors import LogNorm
    except ImportError:
        fail('matplotlib is missing; install python3-matplotlib (tools/setup.sh does)')
    if classes is not None:
        fig = draw_split(plt, LogNorm, rows, classes, a.title)
        fig.savefig(a.out, dpi=90)
        print(f'wrote {a.out}')
        return 0
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
