"""Drive Advisor: a rules-based design advisor for electromechanical drives."""

__version__ = "0.1.0"
