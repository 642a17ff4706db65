"""Issue 24, "Markdown injection": user text in the ``--format md`` datasheet (a title, motor
names) is escaped as the HTML datasheet escapes it: no heading, link, image or raw HTML of
the user's making reaches a wiki that renders the file."""

import re

import pytest

from advisor.cli import main
from advisor.datasheet.content import Block, Check, Decision, Sheet, Table
from advisor.datasheet.markdown import lead, render, text
from advisor.datasheet.review import Bar, Cycle, Required

TITLE = "Drive\n# heading [link](javascript:alert(1)) ![img](http://x/y.png) <iframe src=x> | a & b"
SCRIPT = "<script>alert(1)</script>"
REQUIREMENT = f"""
[application]
kind = "positioning"
title = {TITLE!r}

[positioning]
profile = "trapezoidal"
travel_rad = 10
load_inertia_kgm2 = 5
load_torque_Nm = 100

[[positioning.motors]]
name = "{SCRIPT}"
speed_rad_s = 150
inertia_kgm2 = 0.01
accel_torque_Nm = 20

[[positioning.motors]]
name = "![m](http://x/y.png)"
speed_rad_s = 300
inertia_kgm2 = 0.004
accel_torque_Nm = 12

[[positioning.motors]]
name = "- [x](javascript:alert(1)) | cell"
speed_rad_s = 100
inertia_kgm2 = 0.03
accel_torque_Nm = 45
""".replace("'", '"')

#: The sections the datasheet writes (level 2) and what a block heading may be (level 3+):
#: every line that begins with ``#`` is one of the datasheet's own headings.
SECTIONS = {
    "## Document",
    "## Summary",
    "## Required and achieved",
    "## Utilisation",
    "## Load cycle",
    "## Parts",
    "## Warnings",
    "## Components",
    "## Checks",
    "## Probability of passing",
    "## Decisions",
    "## Requirements (SI)",
    "## References",
}


def _hostile_md(tmp_path) -> str:
    req = tmp_path / "hostile.toml"
    req.write_text(REQUIREMENT, encoding="utf-8")
    out = tmp_path / "hostile.md"
    assert main(["--batch", str(req), "-o", str(out)]) == 0
    return out.read_text(encoding="utf-8")


def test_a_hostile_requirement_writes_inert_markdown(tmp_path, capsys):
    md = _hostile_md(tmp_path)
    capsys.readouterr()
    for raw in ("<script", "<iframe", "](javascript:", "![", "<", ">"):
        assert raw not in md, raw
    # the title, by hand: the newline a space; \ ` * _ [ ] # | ~ $ backslashed; ( after ]
    # backslashed; < > & as entities
    title = (
        r"Drive \# heading \[link\]\(javascript:alert(1)) !\[img\]\(http://x/y.png) "
        r"&lt;iframe src=x&gt; \| a &amp; b"
    )
    assert md.splitlines()[0] == f"# {title}"
    assert md.count(title) == 2  # the heading and the requirement's title row
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in md
    headings = [line for line in md.splitlines() if line.startswith("#")]
    assert headings[0] == f"# {title}"
    for h in headings[1:]:
        assert h in SECTIONS or re.fullmatch(r"#{3,6} [^#\\].*", h), h
    assert not any(line.startswith(("# heading", "#heading")) for line in md.splitlines())
    # a table row keeps its cell count: the motor name's | is escaped
    row = next(line for line in md.splitlines() if line.startswith(r"| - \[x\]"))
    assert len(re.findall(r"(?<!\\)\|", row)) == 11  # the 10 columns of the candidates


def test_a_commonmark_renderer_makes_no_html_link_or_image_of_it(tmp_path, capsys):
    """Rendered by markdown-it (CommonMark with GFM tables, as rich ships it), the file holds
    no element of the user's making: the only headings are the datasheet's, no <a>, no
    <img>, no <script>, no <iframe>."""
    markdown_it = pytest.importorskip("markdown_it")
    md = _hostile_md(tmp_path)
    capsys.readouterr()
    html = markdown_it.MarkdownIt("commonmark", {"html": True}).enable("table").render(md)
    for tag in ("<a ", "<img", "<script", "<iframe", "<hr", "<blockquote", "<pre", "<ul>\n<li><ul"):
        assert tag not in html, tag
    assert html.count("<h1>") == 1
    assert "<h1>Drive # heading [link](javascript:alert(1)) ![img](http://x/y.png) " in html
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in html


def _sheet(hostile: str) -> Sheet:
    """A datasheet with the hostile text in every field the renderer writes."""
    block = Block(
        hostile,
        rows=[(hostile, hostile, hostile)],
        tables=[Table(hostile, [hostile], [[hostile]])],
        parts=[Block(hostile, rows=[(hostile, "1", "m")])],
    )
    return Sheet(
        title=hostile,
        application=hostile,
        status=hostile,
        version=hostile,
        headline=hostile,
        summary=[(hostile, hostile)],
        requirements=[block],
        components=[block],
        decisions=[Decision(hostile, hostile, hostile, hostile, hostile, hostile)],
        checks=[Check(hostile, hostile, hostile, hostile, hostile, "1.000", "passes", hostile)],
        warnings=[hostile],
        references=[hostile],
        project=[(hostile, hostile)],
        required=[
            Required(
                hostile, hostile, hostile, hostile, hostile, hostile, hostile, "1.000", "passes", 1
            )
        ],
        cycle=Cycle([hostile], [[hostile]], hostile),
        bars=[Bar(hostile, hostile, 0.5, "tight")],
        parts=[[hostile] * 6],
    )


@pytest.mark.parametrize(
    "hostile",
    [
        TITLE,
        SCRIPT,
        "1. first\n- second\n> quote\n    code\n---",
        "=== x\r\n```\n~~~",
        "- a\u2028# b\u2029+ c\x85<d>",
        "\x1b[2J\u202e | x",
    ],
)
def test_every_field_of_the_sheet_is_escaped(hostile):
    md = render(_sheet(hostile))
    for raw in ("<script", "<iframe", "](javascript:", "![", "<d>", "\x1b", "\u202e", "\u2028"):
        assert raw not in md
    lines = md.splitlines()
    ours = {"# ", "## ", "### ", "#### ", "| ", "|---", "- ", "**", "*Source:*", "*Inputs:*"}
    for line in lines:
        if not line or line.startswith(
            ("Drive Advisor ", "Plots: see", "Demand over capacity", r"No \[uncertainty\]")
        ):
            continue
        # every line opens with the datasheet's own mark, or is the rationale paragraph
        assert line.startswith(tuple(ours)) or line == lead(hostile), line
    # no heading, list item or quote begins inside the user's text
    for line in lines:
        for mark in ("# ", "- ", "+ ", "> ", "* "):
            if line.startswith(mark):
                rest = line[len(mark) :].lstrip("#").lstrip()
                assert not rest.startswith(("#", "- ", "+ ", ">", "1. ", "```", "~~~")), line


def test_text_and_lead_by_hand():
    # CommonMark §2.4: a backslash makes ASCII punctuation literal; §2.5: entities
    assert text("a_b*c`d~e$f") == r"a\_b\*c\`d\~e\$f"
    assert text("x](y)") == r"x\]\(y)"
    assert text("a\nb\tc\r\nd") == "a b c  d"
    assert text("\x1b[2J") == r"\\x1b\[2J"  # the control shown as the terminal shows it
    assert lead("- x") == r"\- x" and lead("+ x") == r"\+ x" and lead("12) x") == r"12\) x"
    assert lead("    code") == "code"
    assert lead("-2.52 (≤ 0)") == r"\-2.52 (≤ 0)"
