"""The terminal wizard (textual); imported only when the wizard runs."""
