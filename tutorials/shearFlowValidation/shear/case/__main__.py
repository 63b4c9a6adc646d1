"""python -m shear.case settings|init|settle|progress|post ...: one run's
caseSettings, its initial state, a restart's clean-up, its progress, the
report (shear.case.settings)."""

import sys

from shear.case import settings

sys.exit(settings.main(sys.argv[1:]))
