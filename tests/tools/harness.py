"""What the chart scripts' tests share: run a script's main() with arguments, capturing its
output and exit status, and fail the test with a message.

    from harness import run, check
    code, out, err = run(chart.main, ['sweep.csv', '--front'])
    check(code == 0, 'front exits 0: ' + err)
"""
import contextlib
import io
import sys


def run(main, args):
    """(exit status, stdout, stderr) of main(args); a SystemExit's code counts as the status."""
    out, err = io.StringIO(), io.StringIO()
    code = 0
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(args)
        except SystemExit as e:
            code = e.code
    return code, out.getvalue(), err.getvalue()


def check(condition, what):
    """Ends the test with status 1 and 'FAILED: what' unless condition holds."""
    if not condition:
        print('FAILED: ' + what, file=sys.stderr)
        sys.exit(1)
