"""python -m channel: the tutorial's stages and report (./Allrun)."""

import sys

from channel.case import runs

sys.exit(runs.main(sys.argv[1:]))
