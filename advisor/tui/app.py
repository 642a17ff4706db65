"""The terminal wizard: requirements step by step, an explained design, export.

It calls exactly the engine the batch uses (:func:`advisor.core.engine.advise`), in a worker
thread so the screen never freezes. Every change is saved to a draft in the user's state
directory and offered back at the next start.

Start-up is staged so that the first screen shows within half a second and answers a key at
once: the first step is painted from the file as read (textual and the registry), with the
document shaped and the step shown built (the questions are compiled: a few milliseconds).
The rest waits until that paint is done and the keyboard is quiet (see
:mod:`advisor.tui.startup`): a thread imports the engine and the application and advises
once on the file as given, so that the first ctrl+r finds the modules and catalogs loaded
(and, on a file not edited, that design), and the result views are mounted. The plotting
library is loaded after the first results are painted.
"""

import copy
import time
from pathlib import Path
from typing import Any, ClassVar

import tomli_w
from textual import on
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.widgets import (
    Button,
    ContentSwitcher,
    Header,
    Input,
    Label,
    RadioSet,
    Select,
    Static,
    Switch,
)

from advisor.core import registry
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.io_safety import plain, show
from advisor.tui.keys import KeysInOrder
from advisor.tui.lazy import drafts, fields, fixes
from advisor.tui.results import ResultViews
from advisor.tui.screens import ConfirmScreen, ExportScreen, HelpScreen
from advisor.tui.startup import StartUp
from advisor.tui.steps import StepPages
from advisor.tui.validation import StepChecks
from advisor.tui.widgets import (
    Choice,
    SteadyFooter,
    SteadyLabel,
    SteadyStatic,
    on_off,
    steady_input,
)

__all__ = ["ConfirmScreen", "DriveAdvisorApp", "ExportScreen", "HelpScreen", "run"]

#: The asking steps and the review, as :mod:`advisor.tui.fields` numbers them (its STEPS:
#: the application, the registry's default steps, the review); the first screen lays out
#: their places before that module is imported.
_ASKED = tuple(range(1, len(registry.DEFAULT_STEPS) + 1))
_REVIEW = len(registry.DEFAULT_STEPS) + 1


class DriveAdvisorApp(StartUp, KeysInOrder, StepPages, StepChecks, ResultViews, App[None]):
    """The wizard: the steps, the result views and the export, composed here; how each part
    works is in its own module (:mod:`~advisor.tui.startup`, :mod:`~advisor.tui.keys`,
    :mod:`~advisor.tui.steps`, :mod:`~advisor.tui.validation`, :mod:`~advisor.tui.results`)."""

    TITLE = "Drive Advisor"
    CSS_PATH = "app.tcss"
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar = [
        Binding("ctrl+n", "next", "Next", priority=True),
        Binding("ctrl+b", "back", "Back", priority=True),
        Binding("ctrl+r", "compute", "Compute", priority=True),
        Binding("ctrl+e", "edit", "Edit inputs", priority=True),
        Binding("ctrl+s", "export", "Export", priority=True),
        Binding("left_square_bracket", "plot(-1)", "Prev plot", show=False),
        Binding("right_square_bracket", "plot(1)", "Next plot", show=False),
        Binding("f1", "help", "Help"),
        Binding("ctrl+q", "quit", "Quit", priority=True),
    ]

    def __init__(
        self,
        doc: dict[str, Any] | None = None,
        source: Path | None = None,
        catalog_dir: Path | None = None,
        save_drafts: bool = True,
        offer_draft: bool = True,
        problems: list[str] | None = None,
        warm_up: bool | None = None,
        build_all_steps: bool | None = None,
    ) -> None:
        super().__init__()
        # the document as given; shaped (see _start) once the first screen is painted
        self._given = doc
        self.doc: dict[str, Any] = {}
        self.load_problems: list[str] = list(problems or [])
        self.source = source
        self.catalog_dir = catalog_dir
        self.save_drafts = save_drafts
        # a new requirement is offered the untitled draft; a file, its own draft (if any)
        self.offer_draft = offer_draft and (doc is None or source is not None)
        self.step = 0
        self._last_doc: Any = None  # the document as last saved (or opened)
        #: why the last draft save failed (None: it worked, or none was tried)
        self.draft_unsaved: str | None = None
        self._offered: Any = None  # the draft offered (a drafts.Loaded), while it is
        self._init_start(warm_up)
        self._init_steps(build_all_steps)
        self._init_results()

    def compose(self) -> ComposeResult:
        kind, title = self._first_look()
        yield Header()
        yield SteadyStatic("", id="steps")
        yield SteadyStatic("", id="draft-status")  # shown while the draft cannot be saved
        with ContentSwitcher(initial="wizard", id="main"):
            with ContentSwitcher(initial="step-0", id="wizard"):
                with VerticalScroll(id="step-0", classes="step"):
                    yield Label("What must the drive do?")
                    with RadioSet(id="kind"):
                        for a in registry.applications():
                            yield Choice(a.title, id=f"kind-{a.kind}", value=a.kind == kind)
                    yield SteadyLabel("", id="title-label", classes="name")  # named in _start
                    yield steady_input(title, "f-application-title")
                    yield SteadyStatic("", id="step-0-error", classes="error")
                for s in _ASKED:
                    yield VerticalScroll(id=f"step-{s}", classes="step")
                with VerticalScroll(id=f"step-{_REVIEW}", classes="step"):
                    yield SteadyStatic("", id="review-text")
                    yield SteadyStatic("", id="review-error", classes="error")
            yield Vertical(id="results")  # its views are built by _start
        yield SteadyFooter()

    async def on_mount(self) -> None:
        if self.build_all_steps is None:
            self.build_all_steps = self.is_headless
        # before the first paint: what a key needs costs a few milliseconds now that the
        # questions are compiled, and painted at once it spares a second layout
        await self._start()

    def on_resize(self) -> None:
        if self.is_mounted and self._built.is_set():
            self._show_step(focus=False)

    def _changed(self) -> None:
        now = self._draft_doc()
        if now == self._last_doc:  # a widget reporting what it already showed: no change
            return
        self._last_doc = copy.deepcopy(now)
        if self.save_drafts and self._offered is None:  # not while a draft is being offered
            self._save_draft()
        if self.report is not None:
            self._show_result_status()

    def _draft_doc(self) -> dict[str, Any]:
        """The document as the draft keeps it: a field whose text is refused holds no value
        in the document (what is computed is what the fields show), but the draft keeps its
        text as typed, so a resumed draft shows it again in its field with its message."""
        doc = fields.prune(self.doc)  # new tables at every level: the document stays as is
        for wid in self.field_errors:
            f = self._field_by_id(wid)
            text = self._synced.get(wid, "")
            if f is not None and text.strip():
                fields.put(doc, f.path, fields.kept_text(f, text))
        return doc

    def _save_draft(self) -> None:
        """Save the draft; when it cannot be (its directory is a file, read-only, full …),
        say so once, as a notice and on the status line under the steps, and keep the input
        in memory: a notice at every keystroke would bury the screen. The line stays while
        the saves fail, and goes at the first save that works again."""
        try:
            drafts.save_draft(self._draft_doc(), self.source)
        except OSError as exc:
            why = f"{exc.strerror or type(exc).__name__}"
            if exc.filename:
                why = f"{show(exc.filename, 120)}: {why}"
        except InputError as exc:  # the draft's place is a directory, a FIFO, a device
            why = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        except ValueError as exc:  # text the file's encoding cannot hold (a lone surrogate)
            why = show(exc, 120)
        else:
            if self.draft_unsaved is not None:
                self.draft_unsaved = None
                self._show_draft_status("")
            return
        first = self.draft_unsaved is None
        self.draft_unsaved = why
        self._show_draft_status(
            f"Draft not saved ({why}); your input is kept until you quit: ctrl+s exports it."
        )
        if first:
            self.notify(
                f"the draft cannot be saved ({why})", severity="warning", markup=False, timeout=8
            )

    def _show_draft_status(self, text: str) -> None:
        line = self._by_id("draft-status")
        if line is not None:
            line.update(plain(text))
            line.display = bool(text)

    @on(RadioSet.Changed, "#kind")
    async def _kind_changed(self, event: RadioSet.Changed) -> None:
        kind = (event.pressed.id or "").removeprefix("kind-")
        if kind == self.kind or not self._built.is_set():  # (not the first screen's own)
            return
        keep = {k: v for k, v in self.doc.get("application", {}).items() if k != "kind"}
        self.doc = {"application": {"kind": kind, **keep}, **fields.starting_doc(kind)}
        await self._build_steps()
        self.query_one("#step-0-error", Static).update("")
        self._show_step(focus=False)
        self._changed()

    @on(Input.Changed)
    def _input_changed(self, event: Input.Changed) -> None:
        if not self._built.is_set():  # the first screen's own value, not an edit
            return
        f = self._field_by_id(event.input.id)
        if f is None or self._synced.get(f.id) == event.value:
            return  # (a box just built reports the text the document already holds)
        self._sync_input(f, event.value)
        self._changed()

    @on(Input.Submitted)
    async def _input_submitted(self, event: Input.Submitted) -> None:
        """A submit that was not an enter key (those :meth:`_key_in_order` handles): the
        next field; on the step's last one, the next step."""
        if event.input.id == "export-path" or self._field_by_id(event.input.id) is None:
            return
        event.stop()
        await self._enter_in(event.input)

    @on(Select.Changed)
    def _select_changed(self, event: Select.Changed) -> None:
        f = self._field_by_id(event.select.id)
        if f is None:
            return
        if not isinstance(event.value, str):  # blanked: the field is left out again
            if fields.get(self.doc, f.path) is not None:
                fields.put(self.doc, f.path, None)
                self._changed()
            return
        # a Select built on a real default reports it: the shown default, not a choice the
        # user made (keep the file as it was); a field without one starts blank, so any
        # value it reports, its first choice too, was picked
        unchosen = fields.get(self.doc, f.path) is None and f.default is not None
        if unchosen and event.value == self._shown_choice(f):
            return
        fields.put(self.doc, f.path, event.value)
        self.query_one(f"#{f.id}-err", Label).update("")
        self._changed()

    @on(Switch.Changed)
    def _switch_changed(self, event: Switch.Changed) -> None:
        f = self._field_by_id(event.switch.id)
        if f is not None:
            fields.put(self.doc, f.path, bool(event.value))
            self.query_one(f"#{f.id}-state", Label).update(on_off(bool(event.value)))
            self.query_one(f"#{f.id}-err", Label).update("")
            self._changed()

    @on(Button.Pressed, ".fix Button")
    async def _fix_pressed(self, event: Button.Pressed) -> None:
        fix = self.fixes.get(event.button.id or "")
        if fix is None:
            return
        fixes.apply(self.doc, fix)
        self._changed()
        self.notify(fix.label, title="Changed in the requirement", markup=False)
        self._step_lines.clear()
        await self._build_steps()  # a renamed key now shows in its field
        self._show_step(focus=False)
        if not self._validate(self.step):
            await self._go_to_problem(self.step, "Still to fix")
        else:
            self._focus_step()

    async def action_next(self) -> None:
        if self.query_one("#main", ContentSwitcher).current == "results":
            return
        if not self._validate(self.step):
            self.bell()
            await self._go_to_problem(self.step, "Not yet")
            return
        walk = [s for s, _ in self._walk()]
        if self.step < fields.REVIEW:
            self.step = walk[walk.index(self.step) + 1] if self.step in walk else self.step + 1
            await self._ensure_step(self.step)
            self._show_step()
        else:
            await self.action_compute()

    async def action_back(self) -> None:
        main = self.query_one("#main", ContentSwitcher)
        walk = [s for s, _ in self._walk()]
        if main.current == "results":
            main.current = "wizard"
        elif self.step > 0:
            self.step = walk[walk.index(self.step) - 1] if self.step in walk else self.step - 1
        await self._ensure_step(self.step)
        self._show_step()

    def action_edit(self) -> None:
        self.query_one("#main", ContentSwitcher).current = "wizard"
        self._show_step()

    def action_help(self) -> None:
        self.push_screen(HelpScreen())

    async def action_export(self) -> None:
        problem = self._first_problem()
        if problem is not None:
            await self._go_to_problem(problem, "Not exported")
            return
        stem = self.source.stem if self.source else (self.kind or "drive")
        has_report = self.report is not None and not self._inputs_changed()
        why = ""
        if self.report is None:
            why = f"no report: {self.no_result_why}"
        elif not has_report:
            why = "the inputs changed since the result: ctrl+r before saving the report"
        self.push_screen(ExportScreen(Path.cwd() / f"{stem}.report.toml", has_report, why))

    def write_export(self, path: Path, what: str) -> None:
        from advisor.core.report import to_toml, write_atomic

        if what == "report":
            from advisor.datasheet import format_of, render

            fmt = format_of(path) or "toml"  # design.html: the datasheet, as --format html
            text = to_toml(self.report) if fmt == "toml" else render(self.report, fmt)
        else:
            text = tomli_w.dumps(fields.prune(self.doc))
        write_atomic(path, text)

    async def action_compute(self) -> None:
        if self.computing:
            return
        problem = self._first_problem()
        if problem is not None:
            await self._go_to_problem(problem, "Not computed")
            return
        self.computing = True
        self._started = time.perf_counter()
        self._show_step(focus=False)
        self.query_one("#review-error", Static).update("computing…")
        doc = copy.deepcopy(fields.prune(self.doc))
        self.run_worker(lambda: self._advise(doc), thread=True, exclusive=True, group="advise")

    def _advise(self, doc: dict[str, Any]) -> None:
        self._warmed.wait()  # the warm-up is importing what this needs: let it finish
        from advisor.core.engine import advise
        from advisor.core.reading import parse_requirements

        # the warm-up advised on the file as given: if that is exactly the document to
        # compute (the first ctrl+r on an unedited file), its design is the one (the same
        # function on the same input), taken once
        warm, self._warm_advice = self._warm_advice, None
        self.call_from_thread(self._ensure_results)  # (a key at the first paint: not yet)
        try:
            if warm is not None and warm[0] == doc:
                report = warm[1]
            else:
                report = advise(parse_requirements(doc), self.catalog_dir)
        except InputError as exc:
            self.call_from_thread(self._invalid, exc.messages)
        except InfeasibleError as exc:
            self.call_from_thread(self._infeasible, exc, doc)
        except Exception as exc:  # a bug in a calculation: say so, keep the app and the input
            self.call_from_thread(self._crashed, exc)
        else:
            self.call_from_thread(self._show_report, report, doc)

    @on(Button.Pressed, ".use")
    async def _use_pressed(self, event: Button.Pressed) -> None:
        """Impose the alternative in the requirement, and compute it."""
        opt = self.use_options.get(event.button.id or "")
        if opt is None:
            return
        for path, value in opt.patch:
            fields.put(self.doc, path, value)
        self._changed()
        self._step_lines.clear()
        await self._build_steps()
        self.notify(f"{opt.label}: imposed in the requirement; computing", markup=False)
        await self.action_compute()


def run(path: Path | None, catalog_dir: Path | None) -> int:
    """``advisor`` and ``advisor REQ.toml``: the wizard, prefilled from a file if given.

    The file is read like a batch input (:func:`advisor.core.io_safety.read_toml`); one that
    cannot be read at all is an :class:`InputError` (exit 2, one line); wrong-typed values
    open with the problems shown (:func:`advisor.tui.draft.shape`)."""
    doc = None
    if path is not None:
        from advisor.core.io_safety import read_toml

        doc = read_toml(path)  # shaped by the app, after its first screen
    app = DriveAdvisorApp(doc, path, catalog_dir)
    app.run()
    return 1 if app.return_code else 0
