#!/usr/bin/python3
"""tools/accuracy/chart.py: the Pareto front of a known sweep, the PNG's content, and bad input.

Run by CTest and meson test (tools: chart.py ...). A sweep CSV with the tool's header is written
here with known costs and errors, so the front is known: run B is beaten by A (cheaper and more
accurate), C and D trade cost for error. The chart must show the objects' markers (the blue of
the medians, the red of the p99 crosses), and bad input must exit 2 with a message that names
the fix.
"""
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools', 'accuracy'))
import chart  # noqa: E402
from harness import check  # noqa: E402
from harness import run as run_main  # noqa: E402


def run(args):
    return run_main(chart.main, args)

HEADER = ['scene', 'device', 'width', 'height', 'max_steps', 'threshold_px', 'epsilon', 'step_scale', 'trace_ms',
          'object', 'object_evals', 'class', 'rays', 'depth_px_median', 'depth_px_p99', 'steps_mean']
# (steps, threshold, evals, median, p99): A beats B; A, C, D are the front.
RUNS = [(256, 0.5, 30.0, 0.4, 2.0), (256, 1.0, 40.0, 0.8, 3.0), (512, 0.125, 60.0, 0.1, 0.9),
        (512, 0.03, 90.0, 0.02, 0.3)]


def write_sweep(path):
    with open(path, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(HEADER)
        for steps, th, evals, median, p99 in RUNS:
            for obj in ('mandelbulb', 'julia'):
                for cls in ('interior', 'all'):
                    w.writerow(['paper', 'llvmpipe', 64, 48, steps, th, 1e-4, 1.0, 3.5, obj,
                                evals if obj == 'mandelbulb' else evals / 2, cls, 100, median, p99, 10.0])
            w.writerow(['paper', 'llvmpipe', 64, 48, steps, th, 1e-4, 1.0, 3.5, 'plane', 1.0, 'all', 100, 0.0, 0.0, 1.0])


SWEEP_HEADER = ['scene', 'device', 'width', 'height', 'point', 'label', 'object', 'kind', 'method', 'max_steps',
                'threshold_mode', 'threshold', 'epsilon', 'step_scale', 'relaxation', 'fixed_steps', 'refine', 'normal',
                'normal_scale', 'iterations', 'iteration_mode', 'iteration_detail', 'probe', 'trace_ms', 'object_evals', 'class',
                'rays', 'false_hit_rate', 'depth_px_median', 'depth_px_p99']
# proceduray_sweep's columns: (label, method, relaxation, evals, median, p99, silhouette false-hit rate).
SWEEP_POINTS = [('method=lipschitz threshold=0.5', 'lipschitz', 1.0, 20.0, 0.05, 0.5, 0.02),
                ('method=relaxed relaxation=1.5 threshold=0.5', 'relaxed', 1.5, 15.0, 0.05, 0.6, 0.01),
                ('d3d12 sample', 'lipschitz', 1.0, 40.0, 0.01, 0.2, 0.0)]


def write_method_sweep(path):
    with open(path, 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(SWEEP_HEADER)
        for i, (lab, method, relax, evals, median, p99, fat) in enumerate(SWEEP_POINTS):
            for cls in ('silhouette_1px', 'all'):
                w.writerow(['d3d12', 'llvmpipe', 32, 32, i, lab, 'cog', 'sdf', method, 512, 'footprint', 0.5, 1e-4, 1,
                            relax, 64, 'on', 'central', 1, 0, 'fixed', 0.01, 2, 1.5, evals, cls, 100,
                            fat if cls == 'silhouette_1px' else 0.001, median, p99])


def main():
    with tempfile.TemporaryDirectory() as d:
        sweep = os.path.join(d, 'sweep.csv')
        write_sweep(sweep)
        code, out, _ = run([sweep, '--front', '--object', 'mandelbulb'])
        check(code == 0, 'front exits 0')
        line = out.strip()
        check(line.startswith('mandelbulb: '), 'front names the object: ' + line)
        runs = [part.split(':')[0] for part in line[len('mandelbulb: '):].split('; ')]
        check(runs == ['256 st, 0.5 px', '512 st, 0.125 px', '512 st, 0.03 px'], 'front is A, C, D: ' + repr(runs))
        check(chart.pareto_front([(1, 5), (2, 5), (3, 1)]) == [(1, 5), (3, 1)], 'a tie in error keeps the cheaper')
        # The plane's zero errors cannot sit on a log axis: it is left out, not an error.
        code, out, _ = run([sweep, '--front'])
        check(code == 0 and 'plane' not in out and 'julia' in out, 'every object with hits: ' + out)

        png = os.path.join(d, 'chart.png')
        code, out, err = run([sweep, '--out', png])
        check(code == 0, 'chart exits 0: ' + err)
        import matplotlib.image
        img = matplotlib.image.imread(png)
        h, w = img.shape[:2]
        check(w > 2 * h, f'two panels side by side: {w}x{h}')
        rgb = img[:, :, :3]
        blue = ((rgb[:, :, 2] > 0.6) & (rgb[:, :, 0] < 0.3)).sum()   # tab:blue markers and front
        red = ((rgb[:, :, 0] > 0.75) & (rgb[:, :, 1] < 0.3) & (rgb[:, :, 2] < 0.3)).sum()  # tab:red crosses
        check(blue > 200, f'median markers drawn ({blue} blue pixels)')
        check(red > 50, f'p99 markers drawn ({red} red pixels)')

        code, _, err = run([sweep, '--out', png, '--object', 'teapot'])
        check(code == 2 and 'no measured hits of teapot' in err and 'mandelbulb' in err, 'unknown object: ' + err)
        code, _, err = run([sweep, '--front', '--cost', 'speed'])
        check(code == 2 and "unknown cost 'speed'" in err and 'object_evals' in err, 'unknown cost: ' + err)
        bad = os.path.join(d, 'bad.csv')
        with open(bad, 'w') as f:
            f.write('a,b\n1,2\n')
        code, _, err = run([bad, '--front'])
        check(code == 2 and 'no proceduray_accuracy header' in err, 'foreign CSV: ' + err)
        code, _, err = run([os.path.join(d, 'missing.csv'), '--front'])
        check(code == 2 and 'cannot read' in err, 'missing CSV: ' + err)
        code, _, err = run([sweep])
        check(code == 2 and 'pass --out PNG or --front' in err, 'nothing to do: ' + err)
        # proceduray_sweep's CSV: labels from the knob columns, the sample's settings named, silhouettes.
        methods = os.path.join(d, 'methods.csv')
        write_method_sweep(methods)
        code, out, err = run([methods, '--front'])
        check(code == 0, 'sweep front exits 0: ' + err)
        runs = [part.split(':')[0] for part in out.strip()[len('cog: '):].split('; ')]
        check(runs == ['relaxed w1.5 0.5px', 'D3D12 sample'], 'sweep front, labelled by knobs: ' + repr(runs))
        code, out, err = run([methods, '--front', '--error', 'silhouette'])
        check(code == 0 and out.startswith('cog: relaxed w1.5 0.5px: 15 object_evals, median 1 px; D3D12 sample: 40'),
              'silhouette front in percent: ' + out + err)
        code, out, err = run([methods, '--out', png, '--error', 'silhouette'])
        check(code == 0 and os.path.getsize(png) > 1000, 'silhouette chart written: ' + err)
        code, _, err = run([methods, '--front', '--error', 'width'])
        check(code == 2 and "unknown error 'width'; pass depth or silhouette" in err, 'unknown error: ' + err)
    print('chart.py: fronts, PNG content and bad input as expected')
    return 0


if __name__ == '__main__':
    sys.exit(main())
