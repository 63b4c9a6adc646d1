"""The channel case: presets, caseSettings and the initial flow
(settings), the particles (particles), the stages' driver (runs)."""
