#!/usr/bin/python3
"""tools/accuracy/heatmap.py: a known count grid drawn where it should be, split by ray class, and
bad input refused.

A 40 x 20 grid of zeros (black, no march) with a block of 200 evaluations on the right half:
the PNG's right half must be bright (the colour map's top) and its left half dark.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools', 'accuracy'))
import heatmap  # noqa: E402
from harness import check  # noqa: E402
from harness import run as run_main  # noqa: E402


def run(args):
    return run_main(heatmap.main, args)


def check_split(d, png):
    """--classes: hits (200 evaluations) in the first panel, far misses (2) in the last; mismatches refused."""
    steps, classes = os.path.join(d, 'split_steps.csv'), os.path.join(d, 'classes.csv')
    with open(steps, 'w') as f, open(classes, 'w') as c:
        for y in range(30):
            f.write(','.join('200' if x < 10 else ('40' if x < 20 else '2') for x in range(30)) + '\n')
            c.write(','.join('1' if x < 10 else ('2' if x < 20 else '3') for x in range(30)) + '\n')
    code, out, err = run([steps, '--classes', classes, '--out', png])
    check(code == 0, 'split heat map exits 0: ' + err)
    import matplotlib.image
    img = matplotlib.image.imread(png)[:, :, :3]
    w = img.shape[1]
    r, g, b = img[:, :, 0], img[:, :, 1], img[:, :, 2]
    bright = (r > 0.9) & (g > 0.8) & (b < 0.8)        # inferno's top, pale yellow: the hits' 200
    dark = (r < 0.25) & (b - g > 0.1)                  # its bottom, deep purple: the far misses' 2
    cols_bright, cols_dark = bright.any(axis=0).nonzero()[0], dark.any(axis=0).nonzero()[0]
    # The colour bar, right of the panels, holds both ends of the scale: look left of it only.
    bar = cols_bright.max()
    panels = cols_bright[cols_bright < bar - 30]
    check(len(panels) > 0 and panels.max() < w / 3, 'the hits drawn in the first panel, and only there')
    far = cols_dark[cols_dark < bar - 30]
    check(len(far) > 0 and far.min() > w / 2, 'the far misses drawn in the last panel')
    small = os.path.join(d, 'small.csv')
    with open(small, 'w') as f:
        f.write('1,1\n')
    code, _, err = run([steps, '--classes', small, '--out', png])
    check(code == 2 and 'is 2x1, the steps grid 30x30' in err, 'a class grid of another size: ' + err)
    bad = os.path.join(d, 'bad.csv')
    with open(bad, 'w') as f:
        for y in range(30):
            f.write(','.join('7' for x in range(30)) + '\n')
    code, _, err = run([steps, '--classes', bad, '--out', png])
    check(code == 2 and 'a class other than 0' in err, 'an unknown class code: ' + err)


def main():
    with tempfile.TemporaryDirectory() as d:
        grid = os.path.join(d, 'steps.csv')
        with open(grid, 'w') as f:
            for y in range(20):
                f.write(','.join('200' if x >= 20 else ('4' if x == 19 else '0') for x in range(40)) + '\n')
        png = os.path.join(d, 'heat.png')
        code, out, err = run([grid, '--out', png, '--title', 'test'])
        check(code == 0, 'heat map exits 0: ' + err)
        import matplotlib.image
        img = matplotlib.image.imread(png)[:, :, :3]
        h, w = img.shape[:2]
        # The image area: find the bright block (inferno's top is near yellow: r, g high) and the black.
        bright = (img[:, :, 0] > 0.9) & (img[:, :, 1] > 0.8)
        black = (img.sum(axis=2) < 0.05)
        cols_bright = bright.any(axis=0).nonzero()[0]
        cols_black = black.any(axis=0).nonzero()[0]
        check(len(cols_bright) > 0 and len(cols_black) > 0, 'bright and black areas drawn')
        check(cols_bright.mean() > cols_black.mean(), 'the 200-evaluation block is right of the unmarched block')
        check_split(d, png)
        ragged = os.path.join(d, 'ragged.csv')
        with open(ragged, 'w') as f:
            f.write('1,2,3\n1,2\n')
        code, _, err = run([ragged, '--out', png])
        check(code == 2 and 'rows differ in length' in err, 'ragged rows: ' + err)
        text = os.path.join(d, 'text.csv')
        with open(text, 'w') as f:
            f.write('1,x\n')
        code, _, err = run([text, '--out', png])
        check(code == 2 and 'not a number' in err, 'non-numeric: ' + err)
        code, _, err = run([os.path.join(d, 'missing.csv'), '--out', png])
        check(code == 2 and 'cannot read' in err, 'missing: ' + err)
    print('heatmap.py: a known grid drawn in place, bad input refused')
    return 0


if __name__ == '__main__':
    sys.exit(main())
