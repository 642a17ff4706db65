"""Sources a reader can follow (issue 12, item 9): every rule, check and catalog row cites
ids of catalogs/bibliography.toml, and every report carries exactly the entries it cites."""

import re
import tomllib
from pathlib import Path

import pytest

import rules  # noqa: F401 - registers every rule
from advisor.core.cite import cite, note, text
from advisor.core.engine import advise
from advisor.core.errors import CatalogError
from advisor.core.reading import read_requirements
from advisor.core.report import SourceOut, to_toml
from advisor.core.rulebook import REGISTRY
from catalogs import load_catalogs
from catalogs.loader import BIBLIOGRAPHY_FILE, HERE, MOTORS_FILE
from tests.helpers import EXAMPLES

SEEDS = Path("/work/shared/seeds")


@pytest.fixture(scope="module")
def cat():
    return load_catalogs()


@pytest.fixture(scope="module")
def shipped_ids():
    with (HERE / BIBLIOGRAPHY_FILE).open("rb") as fh:
        return {e["id"] for e in tomllib.load(fh)["source"]}


def test_every_rule_cites_the_bibliography(cat):
    assert REGISTRY
    for r in REGISTRY.values():
        assert r.source.ids, r.id
        assert set(r.source.ids) <= set(cat.bibliography), r.id


def test_every_catalog_row_resolves_to_a_shipped_entry(cat, shipped_ids):
    # the shipped catalogs add no entries of their own: all of them are in the bibliography file
    assert set(cat.bibliography) == shipped_ids
    for m in cat.motors:
        assert cat.motor_sources[m.source][0] in shipped_ids
    for s in cat.electrical_steels:
        assert s.source and all(cat.steel_sources[k][0] in shipped_ids for k in s.source)
    for b in cat.bearings:
        assert b.source and all(cat.bearing_sources[k][0] in shipped_ids for k in b.source)
    for key, (ref, _) in cat.materials.sources.items():
        assert ref in shipped_ids, key


def test_the_seed_entries_name_their_files_and_authors(cat):
    seeds = {i: e for i, e in cat.bibliography.items() if i.startswith("seed-")}
    assert sorted(seeds) == ["seed-000", "seed-001", "seed-002", "seed-003", "seed-004"]
    for i, e in seeds.items():
        assert re.fullmatch(rf"{i[-3:]}_[0-9a-f]{{16}}\.txt", e["file"])
        assert e["authors"] and e["title"] and e["journal"]
        if SEEDS.is_dir():
            assert (SEEDS / e["file"]).is_file()
    assert cat.bibliography["seed-003"]["year"] == 1965
    assert cat.bibliography["seed-003"]["volume"] == "153"
    # a journal the seed text does not name is not invented
    assert cat.bibliography["seed-000"]["journal"] == "journal not named in the seed text"


@pytest.mark.parametrize("example", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_each_example_report_carries_exactly_the_sources_it_cites(example, cat):
    report = tomllib.loads(to_toml(advise(read_requirements(example))))
    cited = set()
    for item in report["decisions"] + report["checks"]:
        cited |= set(item["sources"])
        assert "source" in item
        # readable: no raw seed file names in the text beside the ids
        assert not re.search(r"\d{3}_[0-9a-f]{16}\.txt", item["source"]), item["source"]
    listed = [s["id"] for s in report["sources"]]
    assert len(listed) == len(set(listed))
    assert set(listed) == cited
    for s in report["sources"]:
        assert s == {k: v for k, v in cat.bibliography[s["id"]].items()}
    # every decision rests on at least one published source
    assert all(d["sources"] for d in report["decisions"])


def test_the_citation_text_names_each_source_once():
    c = cite("seed-000", "eqs. (4), (5)") + cite("en-10106") + cite("seed-000", "table 2")
    short = {"seed-000": "Baranov et al. (seed 000)", "en-10106": "EN 10106"}
    assert c.ids == ["seed-000", "en-10106"]
    assert text(c, short) == "Baranov et al. (seed 000), eqs. (4), (5) and table 2; EN 10106"
    assert text(c.with_note("at 5000 rpm"), short).endswith("EN 10106: at 5000 rpm")
    assert text(note("the requirement's [envelope]"), short) == "the requirement's [envelope]"
    assert cite("seed-003").at("eq. (3)").refs == (("seed-003", "eq. (3)"),)


def test_the_full_reference_reads_like_a_bibliography_line(cat):
    ref = SourceOut.make(**cat.bibliography["seed-003"]).reference()
    assert ref.startswith("Trofimuk I. P. Выбор рационального передаточного числа")
    assert "vol. 153" in ref and "1965" in ref and "003_9e41cc3901572aaa.txt" in ref


def _user_dir(tmp_path: Path, sources: str) -> Path:
    d = tmp_path / "cat"
    d.mkdir(parents=True)
    shipped = (HERE / MOTORS_FILE).read_text(encoding="utf-8")
    rest = shipped.split("[sources]", 1)[1]
    rows = rest[rest.index("[[motor]]") :].split("[[motor]]")[1]
    row = re.sub(r'model = "4A(\w+)"', r'model = "X\1"', "[[motor]]" + rows)
    row = re.sub(r'source = "[^"]+"', 'source = "mine"', row)
    (d / MOTORS_FILE).write_text(f"[sources]\n{sources}\n\n{row}", encoding="utf-8")
    return d


def test_a_catalog_source_that_is_not_in_the_bibliography_is_refused(tmp_path):
    d = _user_dir(tmp_path, 'mine = { id = "no-such-book", note = "p. 3" }')
    with pytest.raises(CatalogError, match="'no-such-book' is not an id of the bibliography"):
        load_catalogs(d)


def test_a_user_catalog_may_cite_a_shipped_entry_or_bring_its_own(tmp_path):
    d = _user_dir(tmp_path, 'mine = { id = "4a-table", note = "my copy, p. 12" }')
    cat = load_catalogs(d)
    assert cat.motor_sources["mine"] == ("4a-table", "my copy, p. 12")
    d2 = _user_dir(tmp_path / "2", 'mine = "bench measurements, lab book 7"')
    cat2 = load_catalogs(d2)
    assert cat2.bibliography["mine"]["title"] == "bench measurements, lab book 7"
