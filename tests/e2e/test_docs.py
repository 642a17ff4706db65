"""The documentation holds together: the README stays a short front page (the two commands,
a tour, a map of docs/), and every link in it and in docs/ leads to a file that exists and,
where it names a section, to a heading of that file."""

import re
from pathlib import Path

ROOT = Path(__file__).parents[2]
README = ROOT / "README.md"
DOCS = sorted((ROOT / "docs").rglob("*.md"))

#: [text](target) in Markdown, not an image; the target without a title.
LINK = re.compile(r"(?<!!)\[[^\]\n]*\]\(([^)\s]+)\)")


def _links(path: Path) -> list[str]:
    text = path.read_text(encoding="utf-8")
    text = re.sub(r"```.*?```", "", text, flags=re.S)  # links inside code blocks are code
    return [t for t in LINK.findall(text) if not re.match(r"[a-z]+:", t)]


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    s = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return s.replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    return {_slug(h) for h in re.findall(r"^#+ (.+)$", text, flags=re.M)}


def test_slug_as_github_makes_it():
    assert _slug("Where this advisor departs from the seeds, and why") == (
        "where-this-advisor-departs-from-the-seeds-and-why"
    )
    assert _slug("Family studies on Dask") == "family-studies-on-dask"
    assert _slug("Motor frames of the rotary actuator (issue 25)") == (
        "motor-frames-of-the-rotary-actuator-issue-25"
    )


def test_the_readme_is_a_front_page_under_300_lines():
    text = README.read_text(encoding="utf-8")
    assert len(text.splitlines()) < 300
    # the two commands, exactly (.ci/run runs the second)
    install = (
        "python3 -m venv .venv && .venv/bin/pip install -e '.[test,report,family]' && "
        ".venv/bin/advisor --batch examples/linear_screw_actuator.toml -o design.toml"
    )
    assert install in text.splitlines()
    assert ".venv/bin/python -m pytest -q" in text.splitlines()
    assert "python -m pytest -q" in (ROOT / ".ci" / "run").read_text(encoding="utf-8")


def test_the_readme_maps_every_doc():
    linked = {(README.parent / t.split("#")[0]).resolve() for t in _links(README)}
    assert {p.resolve() for p in DOCS} <= linked


def test_every_link_leads_to_a_file_and_a_heading():
    broken = []
    for page in [README, *DOCS]:
        for target in _links(page):
            path, _, anchor = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            if not dest.exists():
                broken.append((page.name, target))
            elif anchor and dest.suffix == ".md" and anchor not in _anchors(dest):
                broken.append((page.name, target))
    assert broken == []


def test_the_readme_links_into_docs():
    """Counted by hand from the README's map: 4 tutorials, 2 guides, 16 reference pages and
    the developer's page (a map that loses its rows fails here)."""
    targets = {t.split("#")[0] for t in _links(README) if t.startswith("docs/")}
    assert len([t for t in targets if t.startswith("docs/tutorials/")]) == 4
    assert len([t for t in targets if t.startswith("docs/reference/")]) == 16
    assert {"docs/wizard.md", "docs/family.md", "docs/developing.md"} <= targets
