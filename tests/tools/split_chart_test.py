#!/usr/bin/python3
"""tools/accuracy/split_chart.py: a known split drawn bar by bar, and bad input refused.

Two objects: 'tall' whose near misses cost 90 evaluations per ray against its hits' 10, and
'flat' at 10 and 10. The tall near-miss bar (orange) must reach far higher in the image than
any blue bar, and only in the first panel.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools', 'accuracy'))
import split_chart  # noqa: E402
from harness import check  # noqa: E402
from harness import run as run_main  # noqa: E402


def run(args):
    return run_main(split_chart.main, args)


ROWS = ['object,class,rays,evaluations,evals_per_ray,share',
        'tall,hit,100,1000,10,0.1', 'tall,near_miss,50,4500,90,0.45',
        'flat,hit,100,1000,10,0.1', 'flat,near_miss,100,1000,10,0.1']


def write(path, rows):
    with open(path, 'w') as f:
        f.write('\n'.join(rows) + '\n')


def main():
    with tempfile.TemporaryDirectory() as d:
        good, png = os.path.join(d, 'split.csv'), os.path.join(d, 'split.png')
        write(good, ROWS)
        code, out, err = run([good, '--out', png])
        check(code == 0, 'chart exits 0: ' + err)
        import matplotlib.image
        img = matplotlib.image.imread(png)[:, :, :3]
        h, w = img.shape[:2]
        r, g, b = img[:, :, 0], img[:, :, 1], img[:, :, 2]
        orange = (r > 0.8) & (g > 0.4) & (g < 0.65) & (b < 0.35)
        blue = (b > 0.7) & (r < 0.35)
        rows_o, cols_o = orange.nonzero()
        rows_b = blue.nonzero()[0]
        check(len(rows_o) > 0 and len(rows_b) > 0, 'orange and blue bars drawn')
        # The tall near-miss bar (9x the hits) reaches far higher (a smaller row) than any blue bar.
        tall = rows_o[cols_o < w / 2]
        check(len(tall) > 0 and tall.min() < rows_b.min() - 0.3 * (rows_b.max() - rows_b.min() + 20),
              'the 90-evaluation bar towers over the 10-evaluation ones')
        code, _, err = run([good, '--out', png, '--objects', 'nope'])
        check(code == 2 and "has no object 'nope'; it has tall, flat" in err, 'unknown object: ' + err)
        bad = os.path.join(d, 'bad.csv')
        write(bad, ROWS[:1] + ['tall,miss,1,1,1,0.1'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and "class 'miss' is not hit, near_miss or far_miss" in err, 'unknown class: ' + err)
        write(bad, ROWS[:1] + ['tall,hit,1,1,-1,0.1'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'negative or non-finite' in err, 'negative: ' + err)
        write(bad, ['object,class,rays', 'tall,hit,1'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'lacks a column' in err, 'missing column: ' + err)
        code, _, err = run([os.path.join(d, 'missing.csv'), '--out', png])
        check(code == 2 and 'cannot read' in err, 'missing file: ' + err)
    print('split_chart.py: a known split drawn in place, bad input refused')
    return 0


if __name__ == '__main__':
    sys.exit(main())
