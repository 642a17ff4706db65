"""Citations: which sources of the bibliography (catalogs/bibliography.toml) a rule, a check
or a catalog row rests on, and where in them.

A :class:`Cite` holds bibliography ids with a place in each source (``eq. (9)``, ``table 3``)
and an optional note. The report lists the ids of every decision and check (``sources``), a
readable text beside them (``source``: "Baranov et al. (seed 000), eq. (9)"), and the full
entry of each cited id as ``[[sources]]``. The text is written from the bibliography's short
names, so a source is named the same way everywhere.
"""

from collections.abc import Iterable, Mapping
from typing import Any, NamedTuple


class Cite(NamedTuple):
    """Bibliography ids with the place cited in each, and a note on what was taken."""

    refs: tuple[tuple[str, str], ...] = ()
    note: str = ""

    @property
    def ids(self) -> list[str]:
        """The cited ids, each once, in order."""
        return list(dict.fromkeys(i for i, _ in self.refs))

    def at(self, where: str) -> "Cite":
        """The same sources, the last one at the place ``where`` (``eq. (14)``)."""
        if not self.refs:
            raise ValueError("a citation without a source has no place to point at")
        *head, (last, _) = self.refs
        return Cite((*head, (last, where)), self.note)

    def with_note(self, note: str) -> "Cite":
        return Cite(self.refs, note)

    def __add__(self, other: Any) -> "Cite":  # type: ignore[override]
        if not isinstance(other, Cite):
            return NotImplemented
        note = "; ".join(n for n in (self.note, other.note) if n)
        return Cite(self.refs + other.refs, note)


def cite(id: str, where: str = "") -> Cite:
    """One source of the bibliography, optionally at a place in it."""
    return Cite(((id, where),))


def note(text: str) -> Cite:
    """A basis that is no published source (the requirement itself, a stated margin)."""
    return Cite((), text)


def text(c: Cite, short: Mapping[str, str]) -> str:
    """The readable citation: "Baranov et al. (seed 000), eq. (9); GOST 12139-84: note"."""
    places: dict[str, list[str]] = {}
    for i, w in c.refs:  # one source named once, with every place cited in it
        places.setdefault(i, [])
        if w and w not in places[i]:
            places[i].append(w)
    body = "; ".join(
        ", ".join([short.get(i, i), " and ".join(ws)]) if ws else short.get(i, i)
        for i, ws in places.items()
    )
    if c.note:
        return f"{body}: {c.note}" if body else c.note
    return body


def cited_ids(groups: Iterable[Iterable[str]]) -> list[str]:
    """Every id of the groups, each once, in the order of first citation."""
    return list(dict.fromkeys(i for g in groups for i in g))
