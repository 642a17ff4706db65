"""Adding an application is one package plus one registration: a toy application (a hand
lever) is registered from inside this test and run through the CLI — one file, many files,
``-o`` — and through the wizard, without touching any other file."""

import tomllib
from types import SimpleNamespace
from typing import Annotated

import pytest
from textual.widgets import Input, Label, Static

from advisor.calc.sizing import Check
from advisor.cli import main
from advisor.core import registry
from advisor.core.report import ReportTable
from advisor.core.requirements import ApplicationReq, StrictModel, number_field
from advisor.tui.app import DriveAdvisorApp


class LeverReq(StrictModel):
    force_N: Annotated[
        float, number_field(gt=0, le=1e4, desc="hand force, N", label="Hand force", step=1)
    ]
    arm_m: Annotated[
        float, number_field(gt=0, le=5, desc="lever arm, m", label="Lever arm", step=1)
    ]
    limit_Nm: Annotated[
        float,
        number_field(gt=0, le=1e4, desc="torque the shaft takes, N·m", label="Shaft limit", step=3),
    ] = 100.0


class LeverRequirements(StrictModel):
    application: ApplicationReq
    lever: LeverReq


class LeverOut(ReportTable):
    torque_Nm: float


def advise_lever(req, cat, trace):
    t = req.lever.force_N * req.lever.arm_m
    check = Check(
        "shaft", "shaft torque", t, req.lever.limit_Nm, "N·m", req.lever.limit_Nm / t, "toy"
    )
    return LeverOut.make(torque_Nm=t), [check], []


def lever_headline(report) -> str:
    return f"lever torque {report.design.torque_Nm:.4g} N·m"


LEVER = registry.Application(
    kind="lever",
    title="Hand lever — a toy application registered by a test",
    requirements=LeverRequirements,
    pipeline=advise_lever,
    headline=lever_headline,
    views=SimpleNamespace(components=lambda r: [], plots=lambda r: []),
)

TOY = """\
[application]
kind = "lever"
title = "toy"

[lever]
force_N = 120.0
arm_m = 0.25
"""


@pytest.fixture(autouse=True)
def lever(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    registry.register(LEVER)
    yield
    registry.unregister("lever")


def test_the_cli_advises_a_registered_application(tmp_path, capsys):
    src = tmp_path / "lever.toml"
    src.write_text(TOY, encoding="utf-8")
    assert main(["--batch", str(src)]) == 0
    rep = tomllib.loads(capsys.readouterr().out)
    assert rep["report"]["application"] == "lever"
    # hand calculation: 120 N × 0.25 m = 30 N·m; the default limit 100 N·m gives 100/30
    assert rep["design"]["torque_Nm"] == 30.0
    assert rep["checks"][0]["margin"] == pytest.approx(3.33333)
    assert rep["requirements"]["lever"]["limit_Nm"] == 100.0

    assert main(["--batch", str(src), "-o", str(tmp_path / "out.toml")]) == 0
    assert "lever torque 30 N·m" in capsys.readouterr().out

    assert main(["--batch", str(src), str(src), "--out-dir", str(tmp_path / "many")]) == 0
    assert capsys.readouterr().out.count("lever torque 30 N·m") == 2


def test_the_registry_decides_which_kinds_are_valid(tmp_path, capsys):
    src = tmp_path / "lever.toml"
    src.write_text(TOY.replace("120.0", "-1.0"), encoding="utf-8")
    assert main(["--batch", str(src)]) == 2
    assert "lever.force_N = -1.0: must be > 0 (hand force, N)" in capsys.readouterr().err
    src.write_text(TOY.replace('"lever"', '"crank"'), encoding="utf-8")
    assert main(["--batch", str(src)]) == 2
    err = capsys.readouterr().err
    assert "application.kind = 'crank': must be one of" in err and "'lever'" in err
    registry.unregister("lever")
    src.write_text(TOY, encoding="utf-8")
    assert main(["--batch", str(src)]) == 2
    assert "'lever'" not in capsys.readouterr().err.split("must be one of")[1]


async def test_the_wizard_asks_and_advises_a_registered_application():
    app = DriveAdvisorApp(save_drafts=False, offer_draft=False)
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.click("#kind-lever")
        await pilot.press("ctrl+n")
        for wid, text in (("f-lever-force-N", "120"), ("f-lever-arm-m", "0.25")):
            app.query_one(f"#{wid}", Input).focus()
            await pilot.press(*text)
        await pilot.press("ctrl+n")
        assert app.step == 3  # it asks nothing in step 2: the wizard skips it
        limit = app.query_one("#f-lever-limit-Nm", Input)
        assert limit.value == "" and limit.placeholder == "default 100"
        label = next(iter(app.query("#step-3 Label.name").results(Label)))
        assert str(label.content) == "Shaft limit [N·m] (optional)"
        await pilot.press("ctrl+n")
        start = app.results_version
        await pilot.press("ctrl+r")
        for _ in range(400):
            await pilot.pause(0.02)
            if app.results_version > start:
                break
        from rich.console import Console

        console = Console(width=200, record=True, file=open(__import__("os").devnull, "w"))
        console.print(app.query_one("#view-summary", Static).content)
        assert "lever torque 30 N·m" in console.export_text()


def test_the_shipped_applications_come_first_and_a_test_may_replace_one():
    """The shipped entries are plain data the registry reads on first use: one registered
    before that comes after them, or replaces the shipped one of its kind."""
    import subprocess
    import sys

    code = (
        "from advisor.core import registry\n"
        "toy = registry.Application('lever', 'toy', None, None, None)\n"
        "registry.register(toy)\n"
        "registry.register(toy._replace(kind='rotary', title='toy rotary'))\n"
        "print(','.join(registry.kinds()))\n"
        "print(registry.application('rotary').title)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.splitlines()
    assert out[0] == "linear,rotary,positioning,spinning_rotor,lever"
    assert out[1] == "toy rotary"
