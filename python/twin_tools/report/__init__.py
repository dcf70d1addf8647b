"""The report of a run: summary.json, report.md and plots (postprocess) and its parts."""
