"""verticalChannel's Python: the paper's downward turbulent channel flow
with four-way coupled 12/4 um quartz particles (doc/cases.md Part A), one
package whose subpackages are its jobs:

  channel.case    the case: presets and each stage's caseSettings, the
                  initial flow (settings), the particles' release, seeded
                  pairs and branch into one cloud per model (particles),
                  the stages' driver behind ./Allrun (runs)
  channel.post    the report: windowed rates and summary (postprocess),
                  the Table D.6 regression and its statements (regression,
                  statements), the report's text and comparison (report),
                  the wall contacts (contacts), the event logs' replay
                  (replay)
  channel.plots   the report's pictures: profiles and the particle picture
                  (profiles), the configurations' matrix (matrix)
  channel.regime  the regime study: its variants (variants), the analysis
                  of a variant (analysis), the grid trend (trend), the
                  one-shortcut pairs (pairs), what a verdict needs (needs),
                  the verdict (verdict), its table and plots (report,
                  plots) and its command (study)

Commands, run in this tutorial's folder (./Allrun is the first):

  python -m channel [options]                 what ./Allrun runs
  python -m channel.case settings|init ...    one stage's caseSettings;
                                              the initial flow
  python -m channel.case.particles release|seedPairs CASE ...
  python -m channel.post PRESET [--reference] the report of a preset
  python -m channel.post.replay PRESET [RUNS] [--reference]
  python -m channel.regime list|run|post ...  the regime study

Tests and benchmarks import it with
aggloTools.runner.tutorial_module("verticalChannel", "channel.<module>").
"""

from pathlib import Path

#: The tutorial's folder: presets, system, constant, 0.orig, runs, results
TUTORIAL = Path(__file__).resolve().parent.parent
