"""python -m shear.study list|settings|post ...: the readings' study
(shear.study.study)."""

import sys

from shear.study import study

sys.exit(study.main(sys.argv[1:]))
