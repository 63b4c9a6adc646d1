"""The shear report: statistics, regression and summary (postprocess),
the statements of App. B (statements), plots (plots), the event logs'
replay (replay), the first contacts replayed spinless (contacts)."""
