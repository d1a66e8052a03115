"""The Lesson 11 lab checker: `python -m checker PATH...` grades lab files headless.

See checker/README.md for the command line, the JSON schema and how to add a lab.
"""
import os

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

__version__ = "1.0"
