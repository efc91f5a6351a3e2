"""`python -m eyesim` runs the `eyesim` command."""

import sys

from eyesim.cli import main

sys.exit(main())
