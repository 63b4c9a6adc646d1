"""python -m channel.regime list|run|post ...: the regime study
(channel.regime.study)."""

import sys

from channel.regime import study

sys.exit(study.main(["channel.regime", *sys.argv[1:]]))
