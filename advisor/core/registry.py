"""The application registry: every application registers here once, and the engine, the
many-file runner, the summaries and the wizard look it up by ``application.kind``.

An entry holds *import paths* (``"package.module:name"``), not imported objects: the batch
path then imports only the application it runs (the linear path no numpy, no path textual),
and listing the applications costs nothing. The shipped applications' entries are plain data
in :mod:`advisor.applications` (``SHIPPED``), read on first use; a new one is one package plus
one :func:`register` call.
"""

from importlib import import_module
from typing import Any, NamedTuple

#: The wizard's asking steps (1 to 4) where an application names none of its own.
DEFAULT_STEPS = ("Loads and motion", "Envelope and holding", "Motor preferences", "Duty cycle")


class Application(NamedTuple):
    """One application: what the wizard lists, how its file is read, how it is advised and
    how its report is summed up. The wizard's questions come from the requirement model's
    field metadata (see :mod:`advisor.core.requirements`).

    Every hook is an import path or the object itself (an application defined in a test).
    The duty cycle needs no hook of its own: the pipeline evaluates the application's cycle
    (phases at the motor through :mod:`advisor.calc.duty`, verdicts by :mod:`rules.duty`)
    and puts an :class:`advisor.duty.report.DutyOut` at ``design.duty``; the datasheet's duty
    plots and the wizard's (:mod:`advisor.duty.views`) draw it from there, and
    ``duty_uses`` says which ``[duty]`` keys the application reads beyond the shared ones.
    A toy application in ``tests/e2e/test_toy_application.py`` uses every hook."""

    kind: str  # the value of application.kind
    title: str  # one line in the wizard's list of applications
    requirements: Any  # "module:Model", the pydantic model of the whole requirement file
    pipeline: Any  # "module:function" (req, catalogs, trace) -> (design, checks, warnings)
    headline: Any  # "module:function" (report) -> the design in a few words
    summary_rows: Any = None  # "module:function" (report) -> [(name, text)] for -o
    views: Any = None  # "module" with components(report) and plots(report), for the wizard
    steps: tuple[str, ...] = DEFAULT_STEPS  # the wizard's names of its asking steps, in order
    # "module:NAME", {requirement path: check id patterns}: which checks cover a requirement
    # (the datasheet's required-vs-achieved table; see :func:`covering`)
    covers: Any = None
    # "module" with DATASHEET_PLOTS, a tuple of functions (report's plain data) -> Plot or
    # None, the application's own datasheet plots, and optionally motor_limits(doc) and
    # working_point(doc) for the shared motor envelope (:mod:`advisor.datasheet.plots`)
    plots: Any = None
    # "module" with key_outputs(report's plain data) -> {column: value} and MEANING
    # ({column: what it means here}): the application's columns of a family study's rows
    # (:mod:`advisor.family.outputs`)
    family: Any = None
    # "module" with margin_model, candidates and restricted: the design's probability of
    # passing under an [uncertainty] table (:mod:`advisor.uncertainty`); None refuses it
    uncertainty: Any = None
    # {[duty] key: the IEC 60034-1 duty types this application also reads it for, beyond
    # the shared table :data:`advisor.core.ignored.DUTY_KEYS_USED`}
    duty_uses: Any = None


_APPLICATIONS: dict[str, Application] = {}
_loaded = False


def register(app: Application) -> Application:
    """Add an application (a second registration of a kind replaces the first)."""
    _APPLICATIONS[app.kind] = app
    return app


def unregister(kind: str) -> None:
    _APPLICATIONS.pop(kind, None)


def _shipped() -> dict[str, Application]:
    global _loaded
    if not _loaded:
        _loaded = True
        shipped = import_module("advisor.applications").SHIPPED
        # the shipped ones first, in their order; one registered before this (a test's)
        # comes after them, or replaces the shipped one of its kind
        added = dict(_APPLICATIONS)
        _APPLICATIONS.clear()
        for entry in shipped:
            register(Application(**entry))
        _APPLICATIONS.update(added)
    return _APPLICATIONS


def applications() -> tuple[Application, ...]:
    """Every registered application, in registration order."""
    return tuple(_shipped().values())


def kinds() -> tuple[str, ...]:
    return tuple(_shipped())


def application(kind: str) -> Application:
    """The entry of ``kind``; a KeyError for an unregistered kind (the requirement model
    refuses those before anything asks)."""
    return _shipped()[kind]


def load(path: Any) -> Any:
    """The object an import path names (``"advisor.applications.linear.advice:advise"``);
    an entry may also hold the object itself (an application defined in a test)."""
    if not isinstance(path, str):
        return path
    module, _, name = path.partition(":")
    obj = import_module(module)
    return getattr(obj, name) if name else obj


def requirements_model(kind: str) -> Any:
    return load(application(kind).requirements)


def pipeline(kind: str) -> Any:
    return load(application(kind).pipeline)


def headline(report: Any) -> str:
    """The design of a report in a few words, as the application words it."""
    return load(application(report.report.application).headline)(report)


def summary_rows(report: Any) -> list[tuple[str, str]]:
    """Rows of the short summary after ``advisor --batch -o``."""
    app = application(report.report.application)
    if app.summary_rows is None:
        return [("design", headline(report))]
    return load(app.summary_rows)(report)


def views(kind: str) -> Any:
    """The wizard's views of an application's report (None: only the generic ones)."""
    app = application(kind)
    return load(app.views) if app.views else None


def covers(kind: str) -> dict[str, tuple[str, ...]]:
    """What an application says its checks cover: a requirement path (``linear.force_N``,
    or a whole table, ``duty``) → the ids of the checks that cover it, ``fnmatch``
    patterns (``duty_*``). Empty where the application says nothing."""
    app = application(kind)
    return dict(load(app.covers)) if app.covers else {}


def datasheet(kind: str) -> Any:
    """The module (or object) of an application's datasheet plots (``DATASHEET_PLOTS``,
    ``motor_limits``, ``working_point``; see :mod:`advisor.datasheet.plots`), None where it
    registers none."""
    app = application(kind)
    return load(app.plots) if app.plots else None


def family_outputs(kind: str) -> Any:
    """The module (or object) giving an application's key outputs in a family study
    (``key_outputs(report)``, ``MEANING``); None where the application gives none."""
    app = application(kind)
    return load(app.family) if app.family else None


def expected_text(values: tuple[str, ...]) -> str:
    """``'a', 'b' or 'c'``: the allowed values, worded as pydantic words a literal error."""
    quoted = [repr(v) for v in values]
    return quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " or " + quoted[-1]


def registered(kind: str) -> str:
    """``kind`` if an application registers it, else a ValueError (the compiled validator's
    check of ``application.kind``; the model's own says it in pydantic's words)."""
    if kind not in kinds():
        raise ValueError(f"unknown application kind {kind!r}")
    return kind
