"""Exit codes of the headless command and the errors that map onto them.

The exit codes are part of the public interface: scripts that call ``advisor --batch`` rely
on them.
"""

from enum import IntEnum


class ExitCode(IntEnum):
    OK = 0
    INTERNAL_ERROR = 1  # a bug: reported in one line, never as a traceback
    INVALID_INPUT = 2  # missing file, broken TOML, bad field, unknown name, bad catalog
    INFEASIBLE = 3  # the input is valid but no design satisfies it


class AdvisorError(Exception):
    """Base of the errors a user can cause; ``str(err)`` is the message shown."""

    exit_code = ExitCode.INTERNAL_ERROR


class InputError(AdvisorError):
    """The requirement (or a file it names) is invalid. One message per problem."""

    exit_code = ExitCode.INVALID_INPUT

    def __init__(self, *messages: str) -> None:
        self.messages = list(messages)
        super().__init__("\n".join(self.messages))


class CatalogError(InputError):
    """A catalog file is broken or inconsistent; the message names file, row and field."""


class InfeasibleError(AdvisorError):
    """No design satisfies the requirement; ``reasons`` says what limited it. Where the
    advice got as far as a design, ``checks`` holds all its checks (the failing ones with
    margin < 1) and ``nearest`` the design in a few words: the report of an infeasible run
    states them (:mod:`advisor.infeasible`)."""

    exit_code = ExitCode.INFEASIBLE

    def __init__(
        self,
        summary: str,
        reasons: list[str],
        *,
        checks: list | None = None,
        nearest: str | None = None,
    ) -> None:
        self.summary = summary
        self.reasons = reasons
        self.checks = list(checks or [])
        self.nearest = nearest
        super().__init__(summary + "".join(f"\n  - {r}" for r in reasons))
