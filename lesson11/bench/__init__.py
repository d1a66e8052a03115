"""Benchmarks: what accuracy costs in time, measured side by side in one run.

    accuracy_cost  the study: tunnelling, solver iterations, contact rule, declared effects, pymunk
    speed          speed side by side: the lesson's listing, the lab's World, the reference solver, pymunk
    listing        the lesson's example solver (its listing's step_world), standalone, for speed
    scenes         the scenes it runs and the accuracy figures it measures on them
    pymunk_pile    the pile scenes rebuilt in pymunk (optional: needs the `compare` extra)
    plot           the figure (optional: needs matplotlib, from the `compare` extra)
    harness        what every benchmark shares: command line, output files, machine note, lockstep

Run the study with `python -m lesson11.bench.accuracy_cost` (a few minutes) or
add `--quick` for a small run in seconds; the same for `python -m lesson11.bench.speed`.
"""
from lesson11.console import safe_output

safe_output()  # every benchmark prints ×, ², μ: a console that is not UTF-8 gets stand-ins
