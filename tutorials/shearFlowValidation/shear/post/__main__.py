"""python -m shear.post PRESET [RUNS [OUT]] | rejudge PRESET: the report
of a preset's runs (shear.post.postprocess)."""

import sys

from shear.post import postprocess

sys.exit(postprocess.main(sys.argv[1:]))
