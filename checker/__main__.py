"""python -m checker PATH...: grade lab files (see checker/README.md)."""
import os
import sys

from .cli import main

try:
    sys.exit(main())
except KeyboardInterrupt:
    print("checker: interrupted", file=sys.stderr)
    sys.exit(130)
except BrokenPipeError:  # the output went to a pipe that closed early (e.g. `| head`)
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    sys.exit(1)
