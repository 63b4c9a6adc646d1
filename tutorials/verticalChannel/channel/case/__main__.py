"""python -m channel.case settings|init ...: one stage's caseSettings,
the initial flow (channel.case.settings)."""

import sys

from channel.case import settings

sys.exit(settings.main(["channel.case", *sys.argv[1:]]))
