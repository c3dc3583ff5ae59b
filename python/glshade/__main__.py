"""``python -m glshade``: the command-line tools of `glshade.lab.cli`."""

import sys

from .lab.cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
