"""One package per application: requirements.py, advice.py, report.py, each registered once."""
