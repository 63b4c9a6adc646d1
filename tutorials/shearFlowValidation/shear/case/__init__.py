"""The shear case: the runs and their caseSettings' entries (entries),
presets, caseSettings and the initial state (settings), the runs'
driver (runs)."""
