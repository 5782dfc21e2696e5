"""``python -m contactlib``: same as the ``contactlib`` console script."""

from contactlib.cli import main

if __name__ == "__main__":
    raise SystemExit(main())
