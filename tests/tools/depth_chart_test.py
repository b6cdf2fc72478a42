#!/usr/bin/python3
"""tools/sweep/depth_chart.py: two known series drawn in their colours, bad input refused."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools', 'sweep'))
import depth_chart  # noqa: E402
from harness import check  # noqa: E402
from harness import run as run_main  # noqa: E402


def run(args):
    return run_main(depth_chart.main, args)


def main():
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, 'depth.csv')
        with open(path, 'w') as f:
            f.write('mode,reflections,trace_ms_median,trace_ms_min,trace_ms_max,width,height,device\n')
            for r in range(9):
                f.write(f'recursive,{r},{1.0 + r},{0.9 + r},{1.1 + r},64,48,test\n')
                f.write(f'iterative,{r},{1.0 + 0.5 * r},{0.9 + 0.5 * r},{1.1 + 0.5 * r},64,48,test\n')
        data, device, _, _ = depth_chart.series(path)
        check(sorted(data) == ['iterative', 'recursive'] and len(data['recursive']) == 9, 'both series read')
        check(data['recursive'][8][1] == 9.0 and device == 'test', 'values read in order')
        png = os.path.join(d, 'depth.png')
        code, _, err = run([path, '--out', png])
        check(code == 0, 'chart exits 0: ' + err)
        import matplotlib.image
        img = matplotlib.image.imread(png)[:, :, :3]
        red = ((img[:, :, 0] > 0.75) & (img[:, :, 1] < 0.3) & (img[:, :, 2] < 0.3)).sum()
        blue = ((img[:, :, 2] > 0.6) & (img[:, :, 0] < 0.3)).sum()
        check(red > 100 and blue > 100, f'both lines drawn ({red} red, {blue} blue pixels)')
        bad = os.path.join(d, 'bad.csv')
        with open(bad, 'w') as f:
            f.write('a,b\n1,2\n')
        code, _, err = run([bad, '--out', png])
        check(code == 2 and 'lacks the columns' in err, 'foreign CSV: ' + err)
        code, _, err = run([os.path.join(d, 'missing.csv'), '--out', png])
        check(code == 2 and 'cannot read' in err, 'missing CSV: ' + err)
    print('depth_chart.py: both modes drawn, bad input refused')
    return 0


if __name__ == '__main__':
    sys.exit(main())
