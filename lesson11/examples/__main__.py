"""Run every example of the lesson in turn: python -m lesson11.examples

Each example's heading says what it shows; its lines are the numbers the
lesson quotes, so you can compare them with the text. Give a name to run just
one, e.g. python -m lesson11.examples bullet_swept.
"""
import importlib
import sys

from lesson11.examples import EXAMPLES


def main(argv=None):
    names = [name for name, _ in EXAMPLES]
    wanted = sys.argv[1:] if argv is None else argv
    unknown = [name for name in wanted if name not in names]
    if unknown:
        print(f"unknown example {unknown[0]!r}; choose from: {', '.join(names)}", file=sys.stderr)
        return 2
    for name, what in EXAMPLES:
        if wanted and name not in wanted:
            continue
        print(f"== {name}: {what}")
        importlib.import_module(f"lesson11.examples.{name}").main()
        print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
