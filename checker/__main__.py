"""python -m checker PATH...: grade lab files (see checker/README.md)."""
import os
import sys

from lesson11.console import safe_output

from checker.isolation import sandbox

safe_output()  # reports use θ, ×, ², ≤: a console that is not UTF-8 gets stand-ins, never a UnicodeEncodeError

if any(not arg.startswith("-") and os.path.exists(arg) for arg in sys.argv[1:]) \
        and sys.argv[1:2] not in (["package"], ["assign"]):
    sandbox.start_zygote()  # there is something to grade: warm the children's zygote while the labs import

from checker.cli import main   # noqa: E402 (imports every lab: numpy, pygame, lesson11)

try:
    sys.exit(main())
except KeyboardInterrupt:
    print("checker: interrupted", file=sys.stderr)
    sys.exit(130)
except BrokenPipeError:  # the output went to a pipe that closed early (e.g. `| head`)
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    sys.exit(1)
