"""python -m channel.post PRESET [--reference]: the report of a preset's
runs (channel.post.postprocess)."""

import sys

from channel.post import postprocess

sys.exit(postprocess.main(sys.argv[1:]))
