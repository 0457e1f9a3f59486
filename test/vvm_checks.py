"""The checks of the Python test scripts: count what holds, print what fails,
and give the summary line and exit code that CTest reads."""

import sys


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
