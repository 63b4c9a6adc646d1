"""The study of the readings the paper leaves open: variants and runs
(study), the first contacts by category (diagnosis), table and plots
(report)."""
