"""The checks of the plots/ scripts' tests (test_critical.py, test_accretion.py): each check
prints ok or FAIL with what it checked; done() ends the test, exit 1 if any failed."""
import sys

failures = []


def check(ok, what):
    print(('ok   ' if ok else 'FAIL ') + what)
    if not ok:
        failures.append(what)


def done(name):
    if failures:
        sys.exit(f'{name}: {len(failures)} checks failed')
    print(f'{name}: every check passed')
