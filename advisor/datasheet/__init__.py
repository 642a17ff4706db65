"""Faces that read a report: the TOML archive, JSON for tools, a Markdown datasheet for
wikis and a self-contained HTML datasheet with plots for a design review.

``render(report, fmt)`` is all a caller needs; matplotlib is imported only for ``html``.
"""

from typing import Any

#: ``--format`` values and the file suffix each writes.
FORMATS = {"toml": ".toml", "json": ".json", "md": ".md", "html": ".html"}


class MissingExtra(RuntimeError):
    """``--format html`` without matplotlib installed."""


def _sheet(report: Any) -> tuple[Any, dict]:
    from advisor.core.registry import covers, headline, summary_rows
    from advisor.core.report import plain
    from advisor.datasheet.content import sheet
    from advisor.datasheet.labels import for_application

    doc = plain(report)
    kind = report.report.application
    labels, defaults = for_application(kind)
    if getattr(report.report, "status", "") == "infeasible":  # no design: say why instead
        from advisor.infeasible import summary_rows as why

        said = report.design.summary
        head, rows = said[:1].upper() + said[1:], why(report)
    else:
        head, rows = headline(report), summary_rows(report)
    s = sheet(doc, head, rows, labels, covers(kind), defaults)
    return s, doc


def render(report: Any, fmt: str) -> str:
    """The report as text in ``fmt`` (one of :data:`FORMATS`)."""
    from advisor.core.report import to_json, to_toml

    if fmt == "toml":
        return to_toml(report)
    if fmt == "json":
        return to_json(report)
    s, doc = _sheet(report)
    if fmt == "md":
        from advisor.datasheet.markdown import render as md

        return md(s)
    if fmt == "html":
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            raise MissingExtra(
                "--format html draws its plots with matplotlib, which is not installed: "
                "pip install 'drive-advisor[report]'"
            ) from None
        from advisor.datasheet.html import render as html
        from advisor.datasheet.plots import plots

        return html(s, plots(doc))
    raise ValueError(f"unknown format {fmt!r}; allowed: {', '.join(FORMATS)}")


def format_of(path: Any) -> str | None:
    """The format a file name asks for by its suffix (``design.html`` → html), if any."""
    suffix = str(path).lower().rsplit(".", 1)[-1] if "." in str(path) else ""
    return next((f for f, s in FORMATS.items() if s == f".{suffix}"), None)
