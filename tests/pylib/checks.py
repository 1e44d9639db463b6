"""Shared by the Python test scripts: soft checks that report every failure,
then one summary line and the exit status (as tests/cli/test_lib.sh does for
the shell tests)."""
import sys

failures = 0


def check(cond, what):
    global failures
    if not cond:
        failures += 1
        print("FAIL:", what)


def finish():
    print("%d failed" % failures)
    sys.exit(1 if failures else 0)
