"""Full references for the sources a report cites by short name.

The rules cite the seed papers by their file in ``/work/shared/seeds`` (``000_….txt``); a
reader of a datasheet has no such folder, so each seed is spelled out here: authors, title
and, where the paper states it, where and when it appeared.
"""

import re

SEEDS = {
    "000": (
        "Seed 000: M. V. Baranov, M. V. Borisov, O. A. Korchagin, N. V. Krylov, "
        "S. L. Samsonovich, V. S. Stepanov. «О выборе скорости электродвигателя и передаточного "
        "числа редуктора привода руля направления транспортного самолёта» (On the choice of "
        "the motor speed and the reducer ratio of a transport aircraft's rudder actuator), "
        "MAI, work of the federal programme 2009–2013."
    ),
    "001": (
        "Seed 001: S. N. Ivanov, M. B. Kolesnik, Yu. B. Koloshenko. «Обеспечение "
        "эксплуатационной совместимости асинхронных двигателей с линейным перемещением "
        "исполнительного механизма» (Ensuring the operational compatibility of asynchronous "
        "motors with linear displacement of the actuator), Komsomolsk-na-Amure State "
        "University."
    ),
    "002": (
        "Seed 002: A. E. Antonov, V. G. Kireyev, I. S. Petukhov. «Увеличение нагрузки на "
        "электропривод при действии гироскопического момента» (The increase of the load on an "
        "electric drive under a gyroscopic moment), Institute of Electrodynamics of the "
        "National Academy of Sciences of Ukraine, Kyiv."
    ),
    "003": (
        "Seed 003: I. P. Trofimuk. «Выбор рационального передаточного числа редуктора для "
        "механизмов с трапецидальным графиком скорости» (Choice of a rational reducer ratio "
        "for mechanisms with a trapezoidal speed graph), Известия Томского политехнического "
        "института, vol. 153, 1965."
    ),
    "004": (
        "Seed 004: N. V. Kraskovskii, S. L. Samsonovich, V. N. Chubikov. «Сравнительный анализ "
        "механизмов однонаправленного действия для электромеханических приводов» (A "
        "comparative analysis of one-way mechanisms for electromechanical drives), Moscow "
        "Aviation Institute."
    ),
}

_SEED_FILE = re.compile(r"\b(\d{3})_[0-9a-f]{16}\.txt")


def readable(source: str) -> str:
    """A source as a reader can follow it: seed files named as "Seed NNN".

    >>> readable("000_e109c3d4c17eaf1c.txt, eq. (14)")
    'Seed 000, eq. (14)'
    """
    return _SEED_FILE.sub(lambda m: f"Seed {m.group(1)}", source)


def cited(sources: list[str]) -> list[str]:
    """The full reference of every seed the sources cite, in seed order."""
    found = {m.group(1) for s in sources for m in _SEED_FILE.finditer(s)}
    found |= {m.group(1) for s in sources for m in re.finditer(r"\bSeed (\d{3})\b", s)}
    return [SEEDS[k] for k in sorted(found) if k in SEEDS]


def entry_text(e: dict) -> str:
    """One entry of the report's bibliography (``[[sources]]``) as a reference line."""
    head = ", ".join(e.get("authors", []))
    parts = [f"{e.get('short', e.get('id', ''))}: {head}." if head else f"{e.get('short', '')}:"]
    if e.get("title"):
        parts.append(f"«{e['title']}»")
    where = [
        str(e[k])
        for k in ("number", "journal", "volume", "institution", "publisher", "year")
        if e.get(k) not in (None, "")
    ]
    if where:
        parts.append(", ".join(where) + ".")
    if e.get("note"):
        parts.append(f"({e['note']})")
    return " ".join(parts)


def references(doc: dict, sources: list[str]) -> list[str]:
    """The report's own bibliography when it has one; an older report without ``[[sources]]``
    gets the seeds its source texts name."""
    entries = doc.get("sources")
    if entries:
        return [entry_text(e) for e in entries]
    return cited(sources)
