"""The channel's report: rates and summary, the Table D.6 regression,
the report's text, the wall contacts, the event logs' replay."""
