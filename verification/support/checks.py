"""What the Python checks of verification/support share: check() records a failed condition with its
message (and prints it at once), and `failures` lists them for the script's exit status."""

import sys

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message, file=sys.stderr)
    return condition
