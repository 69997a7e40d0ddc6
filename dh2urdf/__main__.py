"""``python -m dh2urdf``: the command line (see :mod:`dh2urdf.cli`)."""

from __future__ import annotations

import sys

from dh2urdf.cli import main

if __name__ == "__main__":
    sys.exit(main())
