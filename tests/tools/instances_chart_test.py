#!/usr/bin/python3
"""tools/bench/instances_chart.py: a known crossing drawn where it lies, and bad input refused.

The library's times stay flat (10 ms) while the peer's grow tenfold per decade of instances from
1 ms: the peer's orange line starts below the library's blue one (at 1 instance) and ends far
above it (at 10,000).
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools', 'bench'))
import instances_chart  # noqa: E402
from harness import check  # noqa: E402
from harness import run as run_main  # noqa: E402


def run(args):
    return run_main(instances_chart.main, args)


HEAD = 'device,width,height,instances,library_ms,peer_ms,ratio,coverage,shade,coverage_of_silhouette'
# The device as bench_instances writes it: quoted, for the comma in its name.
ROWS = [HEAD] + [f'"llvmpipe (LLVM 15, 256 bits)",64,64,{n},10,{n},{10 / n},0,0,0' for n in (1, 10, 100, 1000, 10000)]


def write(path, rows):
    with open(path, 'w') as f:
        f.write('\n'.join(rows) + '\n')


def main():
    with tempfile.TemporaryDirectory() as d:
        good, png = os.path.join(d, 'instances.csv'), os.path.join(d, 'instances.png')
        write(good, ROWS)
        code, out, err = run([good, '--out', png])
        check(code == 0, 'chart exits 0: ' + err)
        import matplotlib.image
        img = matplotlib.image.imread(png)[:, :, :3]
        h, w = img.shape[:2]
        r, g, b = img[:, :, 0], img[:, :, 1], img[:, :, 2]
        orange = (r > 0.8) & (g > 0.4) & (g < 0.65) & (b < 0.35)
        blue = (b > 0.7) & (r < 0.35) & (g > 0.35) & (g < 0.6)
        rows_o, cols_o = orange.nonzero()
        rows_b, cols_b = blue.nonzero()
        check(len(rows_o) > 0 and len(rows_b) > 0, 'the library and the peer are drawn')
        # Left (few instances) the peer lies below the library; right, far above it.
        left, right = w * 0.3, w * 0.7
        check(rows_o[cols_o < left].mean() > rows_b[cols_b < left].mean(), 'the peer is cheaper at 1 instance')
        check(rows_o[cols_o > right].mean() < rows_b[cols_b > right].mean() - 0.2 * h, 'the peer is dearer at 10,000')
        bad = os.path.join(d, 'bad.csv')
        write(bad, [HEAD, 'cpu,64,64,0,10,1,10,0,0,0'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'not positive and finite' in err, 'zero instances: ' + err)
        write(bad, ['device,instances', 'cpu,1'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'lacks a column' in err, 'missing column: ' + err)
        write(bad, [HEAD, 'cpu,64,64,ten,10,1,10,0,0,0'])
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'not a number' in err, 'not a number: ' + err)
        code, _, err = run([os.path.join(d, 'none.csv'), '--out', png])
        check(code == 2 and 'cannot read' in err, 'missing file: ' + err)
    print('instances_chart.py: ok')


if __name__ == '__main__':
    main()
