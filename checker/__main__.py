"""python -m checker PATH...: grade lab files (see checker/README.md)."""
import sys

from .cli import main

sys.exit(main())
