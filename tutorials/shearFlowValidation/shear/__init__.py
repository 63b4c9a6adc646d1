"""shearFlowValidation's Python: the paper's laminar shear-flow validation
(Appendix B; doc/cases.md Part B) against van de Ven & Mason's theory and
the Saffman-Turner collision kernel, one package whose subpackages are
its jobs:

  shear.theory  van de Ven & Mason, Saffman-Turner, the B.8 decay
  shear.case    the runs and their caseSettings' entries (entries), the
                presets, caseSettings, initial flow and particles
                (settings), the runs' driver behind ./Allrun (runs)
  shear.post    the report: each run's statistics, the regression and
                summary (postprocess), the statements of App. B
                (statements), the plots (plots), the event logs' replay
                (replay), the first contacts replayed spinless (contacts)
  shear.study   the study of the readings the paper leaves open: its
                variants and runs (study), the first contacts split by
                category (diagnosis), its table and plots (report)

Commands, run in this tutorial's folder (./Allrun is the first):

  python -m shear [options]                     what ./Allrun runs
  python -m shear.case settings|init|settle|progress|post ...
  python -m shear.post PRESET [RUNS [OUT]]      the report of a preset
  python -m shear.post rejudge PRESET
  python -m shear.post.replay PRESET [OUT]
  python -m shear.post.contacts PRESET [RUNS] [OUT]
  python -m shear.study list|settings|post ...  the readings' study

Tests import it with
aggloTools.runner.tutorial_module("shearFlowValidation", "shear.<module>").
"""

from pathlib import Path

#: The tutorial's folder: presets, study, system, constant, 0.orig, runs,
#: results
TUTORIAL = Path(__file__).resolve().parent.parent
