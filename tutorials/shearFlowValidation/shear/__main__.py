"""python -m shear: the tutorial's runs and report (./Allrun)."""

import sys

from shear.case import runs

sys.exit(runs.main(sys.argv[1:]))
