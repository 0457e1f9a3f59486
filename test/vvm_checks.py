"""The checks of the Python test scripts: count what holds, print what fails,
and give the summary line and exit code that CTest reads (Checks); or, where a
script's later steps need the earlier ones to hold, stop at the first failure
(require, which raises Check_failed; run_main prints it and exits with 1)."""

import sys


class Check_failed(Exception):
    pass


def require(condition, message):
    """stops the script's check here unless `condition` holds"""
    if not condition:
        raise Check_failed(message)


def run_main(main):
    """sys.exit(main()), a Check_failed printed as FAILED with exit code 1"""
    try:
        sys.exit(main())
    except Check_failed as e:
        print("FAILED: " + str(e), file=sys.stderr)
        sys.exit(1)


class Checks:
    def __init__(self, name):
        self.name, self.passed, self.failed = name, 0, 0

    def __call__(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("check failed:", what, file=sys.stderr)
        return ok

    def summary(self):
        """Prints the counts; the exit code: 0 when everything held."""
        print(f"{self.name}: {self.passed} passed, {self.failed} failed")
        return 1 if self.failed else 0
