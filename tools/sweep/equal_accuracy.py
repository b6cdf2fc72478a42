#!/usr/bin/python3
"""Against the D3D12 sample's settings at equal accuracy: for each object of proceduray_sweep
CSVs that hold the preset's 'd3d12 sample' point, the cheapest measured setting whose depth
median and p99, silhouette false hits and false misses are all no worse, and its cost ratio.

    tools/sweep/equal_accuracy.py docs/images/methods_alone.csv docs/images/methods_paper.csv

Exit status 2 with a message for a CSV that is not the sweep's or has no sample point.
"""
import csv
import sys


def fail(message):
    print(f'equal_accuracy.py: {message}', file=sys.stderr)
    sys.exit(2)


def number(v):
    return float(v) if v not in ('', None) else 0.0  # an empty field is a rate of no rays: no error


def main(paths):
    if not paths:
        fail('pass CSVs written by proceduray_sweep --preset methods')
    for path in paths:
        try:
            with open(path, newline='') as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            fail(f'cannot read {path}: {e.strerror}')
        if not rows or 'label' not in rows[0] or 'object_evals' not in rows[0]:
            fail(f'{path} is not a proceduray_sweep CSV (no label, object_evals columns)')
        hits = [r for r in rows if r['class'] == 'all' and r['depth_px_median']]
        band = {(r['object'], r['point']): r for r in rows if r['class'] == 'silhouette_1px'}

        def errors(r):
            return (number(r['depth_px_median']), number(r['depth_px_p99']),
                    number(band[(r['object'], r['point'])]['false_hit_rate']), number(r['false_miss_rate']))

        for obj in sorted({r['object'] for r in hits}):
            runs = [r for r in hits if r['object'] == obj]
            sample = [r for r in runs if r['label'] == 'd3d12 sample']
            if not sample:
                fail(f"{path}: {obj} has no 'd3d12 sample' point; sweep with --preset methods")
            bound = errors(sample[0])
            fits = [r for r in runs if all(a <= b + 1e-12 for a, b in zip(errors(r), bound))]
            best = min(fits, key=lambda r: float(r['object_evals']))
            cost, base = float(best['object_evals']), float(sample[0]['object_evals'])
            print(f"{obj:16s} sample {base:6.1f} evaluations (median {bound[0]:.2g}, p99 {bound[1]:.2g} footprints); "
                  f"cheapest at that accuracy {cost:6.1f} ({best['label']}), ratio {cost / base:.2f}")
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
