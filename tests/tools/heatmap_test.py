#!/usr/bin/python3
"""tools/accuracy/heatmap.py: a known count grid drawn where it should be, and bad input refused.

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
