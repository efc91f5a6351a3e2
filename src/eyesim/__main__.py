"""`python -m eyesim` runs the `eyesim` command."""

import sys

from eyesim.app.cli import main

sys.exit(main())
