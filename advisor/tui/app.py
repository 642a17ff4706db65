"""The terminal wizard: requirements step by step, an explained design, export.

It calls exactly the engine the batch uses (:func:`advisor.core.engine.advise`), in a worker
thread so the screen never freezes. Every change is saved to a draft in the user's state
directory and offered back at the next start.
"""

import copy
import time
from pathlib import Path
from typing import Any, ClassVar

import tomli_w
from rich.text import Text
from textual import on
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import (
    Button,
    ContentSwitcher,
    Footer,
    Header,
    Input,
    Label,
    RadioButton,
    RadioSet,
    Select,
    Static,
    Switch,
    TabbedContent,
    TabPane,
)

from advisor.core.errors import InfeasibleError, InputError
from advisor.io_safety import plain, show
from advisor.tui import draft as drafts
from advisor.tui import fields as F
from advisor.tui import views

CSS = """
Screen { layout: vertical; }
#steps { height: 1; padding: 0 1; background: $boost; }
#main { height: 1fr; }
.step { padding: 0 1; }
.field { height: auto; margin: 0; }
.field Vertical { height: auto; width: 1fr; }
.field Label.name { width: 46; padding: 1 1 0 0; }
.field Input { width: 30; }
.field Select { width: 30; }
.error { color: $error; height: auto; padding: 0 0 0 1; }
#step-error { color: $error; height: auto; }
.note { color: $text-muted; height: auto; }
#review-text { height: auto; }
ModalScreen { align: center middle; }
#dialog { width: 80; height: auto; border: thick $primary; padding: 1 2; background: $surface; }
#dialog Horizontal { height: auto; margin-top: 1; }
#dialog Button { margin-right: 1; }
PlotextPlot { height: 24; }
"""

HELP = """\
[b]Drive Advisor — keys[/b]

  ctrl+n   next step (waits until the step is valid)
  ctrl+b   previous step (keeps what you typed)
  ctrl+r   compute the design (from any step; again after an edit)
  ctrl+e   back to the inputs from the results
  ctrl+s   export the report (TOML, JSON, Markdown or HTML) or the requirements
  f1       this help           ctrl+q   quit
  tab / shift+tab move between fields; arrows choose in lists

Every change is saved as a draft and offered back at the next start.
Numbers are SI with the unit shown beside each field.
"""


#: At most this many loading problems are listed (then how many more).
MAX_PROBLEMS = 8


def _input(value: str, id: str) -> Input:
    """An input whose cursor does not blink (a steady screen, and steady snapshots)."""
    box = Input(value, id=id)
    box.cursor_blink = False
    return box


class HelpScreen(ModalScreen[None]):
    BINDINGS: ClassVar = [Binding("escape,f1,q", "dismiss", "Close")]

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Static(HELP, id="help-text")
            yield Button("Close", id="close", variant="primary")

    @on(Button.Pressed, "#close")
    def _close(self) -> None:
        self.dismiss()


class ConfirmScreen(ModalScreen[bool]):
    BINDINGS: ClassVar = [
        Binding("y", "answer(True)", "Yes"),
        Binding("n,escape", "answer(False)", "No"),
    ]

    def __init__(self, question: str, yes: str = "Yes", no: str = "No") -> None:
        super().__init__()
        self.question, self.yes, self.no = question, yes, no

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Static(plain(self.question), id="question")
            with Horizontal():
                yield Button(f"{self.yes} (y)", id="yes", variant="primary")
                yield Button(f"{self.no} (n)", id="no")

    def action_answer(self, value: bool) -> None:
        self.dismiss(value)

    @on(Button.Pressed)
    def _pressed(self, event: Button.Pressed) -> None:
        self.dismiss(event.button.id == "yes")


class ExportScreen(ModalScreen[None]):
    BINDINGS: ClassVar = [Binding("escape", "dismiss", "Cancel")]

    def __init__(self, default: Path, has_report: bool) -> None:
        super().__init__()
        self.default, self.has_report = default, has_report

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Label("Export to (.toml; a report also .json, .md or .html; asks to replace):")
            yield _input(str(self.default), "export-path")
            yield Static("", id="export-error", classes="error")
            with Horizontal():
                yield Button(
                    "Save report", id="save-report", variant="primary", disabled=not self.has_report
                )
                yield Button("Save requirements", id="save-requirements")
                yield Button("Cancel", id="cancel")

    @on(Button.Pressed, "#cancel")
    def _cancel(self) -> None:
        self.dismiss()

    @on(Button.Pressed, "#save-report, #save-requirements")
    def _save(self, event: Button.Pressed) -> None:
        what = "report" if event.button.id == "save-report" else "requirements"
        text = self.query_one("#export-path", Input).value.strip()
        if not text:
            self.query_one("#export-error", Static).update("give a file name")
            return
        path = Path(text).expanduser()
        if what == "requirements" and path.name.endswith(".report.toml"):
            path = path.with_name(path.name.replace(".report.toml", ".toml"))
        if path.exists():
            self.app.push_screen(
                ConfirmScreen(f"{show(path, 200)} exists. Replace it?", "Replace", "Keep it"),
                lambda yes: self._write(path, what) if yes else None,
            )
        else:
            self._write(path, what)

    def _write(self, path: Path, what: str) -> None:
        app = self.app
        assert isinstance(app, DriveAdvisorApp)
        from advisor.datasheet import MissingExtra

        try:
            app.write_export(path, what)
        except OSError as exc:
            self.query_one("#export-error", Static).update(
                plain(f"{path}: cannot write ({exc.strerror}); nothing was written")
            )
            return
        except MissingExtra as exc:
            self.query_one("#export-error", Static).update(plain(str(exc)))
            return
        except InputError as exc:  # a device, a FIFO, a directory: refused, nothing written
            self.query_one("#export-error", Static).update(plain(str(exc)))
            return
        app.notify(f"{what} written to {path}", title="Exported", markup=False)
        self.dismiss()


class DriveAdvisorApp(App[None]):
    TITLE = "Drive Advisor"
    CSS = CSS
    ENABLE_COMMAND_PALETTE = False
    BINDINGS: ClassVar = [
        Binding("ctrl+n", "next", "Next", priority=True),
        Binding("ctrl+b", "back", "Back", priority=True),
        Binding("ctrl+r", "compute", "Compute", priority=True),
        Binding("ctrl+e", "edit", "Edit inputs", priority=True),
        Binding("ctrl+s", "export", "Export", priority=True),
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
    ) -> None:
        super().__init__()
        # any document (a file, a draft, a test's dict) is shaped so that no widget breaks
        shaped, found = drafts.shape(copy.deepcopy(doc)) if doc else ({}, [])
        self.doc: dict[str, Any] = shaped
        self.load_problems: list[str] = [*(problems or []), *found]
        self._draft: drafts.Loaded | None = None
        self.source = source
        self.catalog_dir = catalog_dir
        self.save_drafts = save_drafts
        self.offer_draft = offer_draft and doc is None
        self.step = 0
        self.report = None
        self.computing = False
        self.results_version = 0
        self.last_compute_s = 0.0

    # ------------------------------------------------------------------ layout
    def compose(self) -> ComposeResult:
        yield Header()
        yield Static("", id="steps")
        with ContentSwitcher(initial="wizard", id="main"):
            with ContentSwitcher(initial="step-0", id="wizard"):
                with VerticalScroll(id="step-0", classes="step"):
                    yield Label("What must the drive do?")
                    with RadioSet(id="kind"):
                        for k, text in F.titles().items():
                            yield RadioButton(
                                text,
                                id=f"kind-{k}",
                                value=self.doc.get("application", {}).get("kind") == k,
                            )
                    yield Label(F.title_field().label, classes="name")
                    yield _input(
                        self.doc.get("application", {}).get("title", ""), "f-application-title"
                    )
                    yield Static("", id="step-0-error", classes="error")
                for s in F.ASKED:
                    yield VerticalScroll(id=f"step-{s}", classes="step")
                with VerticalScroll(id=f"step-{F.REVIEW}", classes="step"):
                    yield Static("", id="review-text")
                    yield Static("", id="review-error", classes="error")
            with TabbedContent(id="results"):
                for name in ("Summary", "Components", "Decisions", "Checks", "Plot"):
                    with TabPane(name, id=f"tab-{name.lower()}"):
                        if name == "Plot":
                            yield Static("", id="plot-note", classes="note")
                            yield VerticalScroll(id="plot-box")
                        else:
                            with VerticalScroll():
                                yield Static("", id=f"view-{name.lower()}")
        yield Footer()

    async def on_mount(self) -> None:
        await self._build_steps()
        self._show_step()
        self._show_problems(self.load_problems)
        if self.offer_draft:
            self._draft = loaded = drafts.load_draft()
            if loaded.doc is None and loaded.problems:  # unreadable: set aside, say so
                self._show_problems(loaded.problems)
            elif loaded.doc:
                app = loaded.doc.get("application", {})
                kind = app.get("kind", "?")
                title = show(app.get("title", ""))
                self.push_screen(
                    ConfirmScreen(
                        f"A draft from your last session was found: {kind}"
                        + (f", “{title}”" if title else "")
                        + ".\nResume it?",
                        "Resume",
                        "Start fresh",
                    ),
                    self._resume,
                )

    def _show_problems(self, problems: list[str]) -> None:
        """What loading a file or draft changed or could not use: on the first step and as a
        notification, as plain text (never markup)."""
        if not problems:
            return
        shown = problems[:MAX_PROBLEMS] + (
            [f"… and {len(problems) - MAX_PROBLEMS:,} more"] if len(problems) > MAX_PROBLEMS else []
        )
        text = "\n".join(shown)
        self.query_one("#step-0-error", Static).update(plain(text))
        self.notify(text, title="Loaded with problems", severity="warning", markup=False)

    async def _resume(self, yes: bool | None) -> None:
        loaded = self._draft
        if yes and loaded is not None and loaded.doc is not None:
            self.doc = loaded.doc
            app = self.doc.get("application", {})
            kind = app.get("kind")
            for k in F.titles():
                self.query_one(f"#kind-{k}", RadioButton).value = k == kind
            self.query_one("#f-application-title", Input).value = app.get("title", "")
            await self._build_steps()
            self._show_problems(loaded.problems)
        else:
            drafts.clear_draft()

    @property
    def kind(self) -> str | None:
        return self.doc.get("application", {}).get("kind")

    async def _build_steps(self) -> None:
        kind = self.kind
        for s in F.ASKED:
            box = self.query_one(f"#step-{s}", VerticalScroll)
            await box.remove_children()
            widgets: list[Any] = []
            if kind is None:
                widgets.append(Static("Choose the application first.", classes="note"))
            else:
                specs = F.fields_for(kind, s)
                if not specs:
                    widgets.append(
                        Static("Nothing to set for this application here.", classes="note")
                    )
                note = F.row_note(kind, s)
                if note:
                    widgets.append(Static(note, classes="note"))
                for f in specs:
                    widgets.append(self._field_widget(f))
            widgets.append(Static("", id=f"step-{s}-error", classes="error"))
            await box.mount(*widgets)

    def _field_widget(self, f: F.Field) -> Horizontal:
        value = F.get(self.doc, f.path)
        label = f.label + (f" [{f.unit}]" if f.unit else "") + (" (optional)" if f.optional else "")
        if f.kind == "bool":
            control: Any = Switch(bool(f.default if value is None else value), id=f.id)
        elif f.kind == "choice":
            blank = f.default is None  # no default to show: the field may stay unchosen
            current = value if value in f.choices else self._shown_choice(f)
            if blank and value not in f.choices:
                current = Select.NULL
            control = Select([(c, c) for c in f.choices], value=current, allow_blank=blank, id=f.id)
        else:
            control = _input(F.to_text(f, value), f.id)
            control.placeholder = f.shown_default
        return Horizontal(
            Label(label, classes="name", markup=False),
            Vertical(control, Label("", id=f"{f.id}-err", classes="error")),
            classes="field",
        )

    @staticmethod
    def _shown_choice(f: F.Field) -> str:
        """The choice shown while the file has none: the model's default."""
        return f.default if f.default in f.choices else f.choices[0]

    def _show_step(self) -> None:
        names = " › ".join(
            f"[reverse] {i + 1} {n} [/]" if i == self.step else f"{i + 1} {n}"
            for i, n in enumerate(F.STEPS)
        )
        on_results = self.query_one("#main", ContentSwitcher).current == "results"
        results = "[reverse] Results [/] — ← → views, ctrl+e edit inputs, ctrl+s export"
        self.query_one("#steps", Static).update(results if on_results else names)
        self.query_one("#wizard", ContentSwitcher).current = f"step-{self.step}"
        if self.step == F.REVIEW:
            self.query_one("#review-text", Static).update(self._review_text())

    def _review_text(self) -> str:
        from rich.markup import escape

        text = tomli_w.dumps(F.prune(self.doc)) if self.doc else "(nothing yet)"
        return "[b]Review — the requirement as it will be computed (ctrl+r):[/b]\n\n" + escape(text)

    # ------------------------------------------------------------------ editing
    def _field_by_id(self, wid: str | None) -> F.Field | None:
        if wid == "f-application-title":
            return F.title_field()
        kind = self.kind
        if kind is None or wid is None:
            return None
        return next((f for f in F.all_fields(kind) if f.id == wid), None)

    def _changed(self) -> None:
        if self.save_drafts:
            try:
                drafts.save_draft(F.prune(self.doc))
            except OSError as exc:
                self.notify(
                    f"the draft cannot be saved ({exc.strerror})", severity="warning", markup=False
                )
            except InputError as exc:  # the draft's place is a directory, a FIFO, a device
                self.notify(f"the draft cannot be saved: {exc}", severity="warning", markup=False)

    @on(RadioSet.Changed, "#kind")
    async def _kind_changed(self, event: RadioSet.Changed) -> None:
        kind = (event.pressed.id or "").removeprefix("kind-")
        if kind == self.kind:
            return
        keep = {k: v for k, v in self.doc.get("application", {}).items() if k != "kind"}
        self.doc = {"application": {"kind": kind, **keep}, **F.starting_doc(kind)}
        await self._build_steps()
        self.query_one("#step-0-error", Static).update("")
        self._changed()

    @on(Input.Changed)
    def _input_changed(self, event: Input.Changed) -> None:
        f = self._field_by_id(event.input.id)
        if f is None:
            return
        value, err = F.parse_text(f, event.value)
        label = self.query(f"#{f.id}-err")
        if label:
            label.first(Label).update(plain(err or ""))
        if err is None:
            F.put(self.doc, f.path, value)
            self._changed()

    @on(Select.Changed)
    def _select_changed(self, event: Select.Changed) -> None:
        f = self._field_by_id(event.select.id)
        if f is None:
            return
        if not isinstance(event.value, str):  # blanked: the field is left out again
            if F.get(self.doc, f.path) is not None:
                F.put(self.doc, f.path, None)
                self._changed()
            return
        if F.get(self.doc, f.path) is None and event.value == self._shown_choice(f):
            return  # the shown default, not a choice the user made: keep the file as it was
        F.put(self.doc, f.path, event.value)
        self._changed()

    @on(Switch.Changed)
    def _switch_changed(self, event: Switch.Changed) -> None:
        f = self._field_by_id(event.switch.id)
        if f is not None:
            F.put(self.doc, f.path, bool(event.value))
            self._changed()

    # ------------------------------------------------------------------ validation
    def _validate(self, step: int) -> bool:
        """Field errors of the step, then the engine's own validation of what is known so
        far; messages about later steps wait for those steps."""
        if step == 0:
            if self.kind is None:
                self.query_one("#step-0-error", Static).update("choose an application")
                return False
            return True
        if step == F.REVIEW:
            return True
        kind = self.kind
        assert kind is not None
        ok = True
        for f in F.fields_for(kind, step):
            w = self.query_one(f"#{f.id}")
            if isinstance(w, Input):
                value, err = F.parse_text(f, w.value)
                self.query_one(f"#{f.id}-err", Label).update(plain(err or ""))
                if err is None:  # what is on screen is what is checked
                    F.put(self.doc, f.path, value)
                ok = ok and err is None
        step_msgs: list[str] = []
        for line in self._engine_errors():
            owner = F.error_owner(line, kind, step)
            if owner is None:
                continue
            target = next(
                (f for s in range(1, step + 1) for f in F.fields_for(kind, s) if f.dotted == owner),
                None,
            )
            if owner and target is not None and target in F.fields_for(kind, step):
                self.query_one(f"#{target.id}-err", Label).update(plain(line.split(": ", 1)[-1]))
            else:
                step_msgs.append(line)
            ok = False
        self.query_one(f"#step-{step}-error", Static).update(plain("\n".join(step_msgs)))
        return ok

    def _engine_errors(self) -> list[str]:
        from advisor.core.requirements import parse_requirements

        try:
            parse_requirements(F.prune(self.doc))
        except InputError as exc:
            return exc.messages
        return []

    # ------------------------------------------------------------------ actions
    def action_next(self) -> None:
        if self.query_one("#main", ContentSwitcher).current == "results":
            return
        if not self._validate(self.step):
            self.bell()
            return
        if self.step < F.REVIEW:
            self.step += 1
            self._show_step()
        else:
            self.action_compute()

    def action_back(self) -> None:
        main = self.query_one("#main", ContentSwitcher)
        if main.current == "results":
            main.current = "wizard"
        elif self.step > 0:
            self.step -= 1
        self._show_step()

    def action_edit(self) -> None:
        self.query_one("#main", ContentSwitcher).current = "wizard"
        self._show_step()

    def action_help(self) -> None:
        self.push_screen(HelpScreen())

    def action_export(self) -> None:
        stem = self.source.stem if self.source else (self.kind or "drive")
        self.push_screen(ExportScreen(Path.cwd() / f"{stem}.report.toml", self.report is not None))

    def write_export(self, path: Path, what: str) -> None:
        from advisor.core.report import to_toml, write_atomic

        if what == "report":
            from advisor.datasheet import format_of, render

            fmt = format_of(path) or "toml"  # design.html: the datasheet, as --format html
            text = to_toml(self.report) if fmt == "toml" else render(self.report, fmt)
        else:
            text = tomli_w.dumps(F.prune(self.doc))
        write_atomic(path, text)

    def action_compute(self) -> None:
        if self.computing:
            return
        self.computing = True
        self._started = time.perf_counter()
        self.query_one("#review-error", Static).update("computing…")
        self.run_worker(self._advise, thread=True, exclusive=True, group="advise")

    def _advise(self) -> None:
        from advisor.core.engine import advise
        from advisor.core.requirements import parse_requirements

        doc = copy.deepcopy(F.prune(self.doc))
        try:
            report = advise(parse_requirements(doc), self.catalog_dir)
        except InputError as exc:
            self.call_from_thread(self._invalid, exc.messages)
        except InfeasibleError as exc:
            self.call_from_thread(self._infeasible, exc)
        except Exception as exc:  # a bug in a calculation: say so, keep the app and the input
            self.call_from_thread(self._crashed, exc)
        else:
            self.call_from_thread(self._show_report, report)

    def _done(self) -> None:
        self.computing = False
        self.last_compute_s = time.perf_counter() - self._started
        self.results_version += 1

    def _invalid(self, messages: list[str]) -> None:
        self.step = 4
        self.query_one("#main", ContentSwitcher).current = "wizard"
        self._show_step()
        self.query_one("#review-error", Static).update(
            plain("The requirement is not complete or not valid:\n" + "\n".join(messages))
        )
        self._done()

    def _infeasible(self, exc: InfeasibleError) -> None:
        self.report = None
        self._fill(
            summary=Text.assemble(
                ("No feasible design.", "bold"),
                "\n",
                plain(exc.summary + "\n" + "\n".join(f" • {r}" for r in exc.reasons)),
            )
        )
        self._done()

    def _crashed(self, exc: Exception) -> None:
        self.query_one("#review-error", Static).update(
            plain(
                f"internal error in the calculation ({type(exc).__name__}: {exc}); your input "
                "is kept — please report it with the exported requirements"
            )
        )
        self.notify(f"internal error: {type(exc).__name__}", severity="error")
        self._done()

    def _show_report(self, report) -> None:
        self.report = report
        self._fill(
            summary=views.summary(report),
            components=views.components(report),
            decisions=views.decisions(report),
            checks=views.checks(report),
        )
        self._plot(report)
        self._done()

    def _fill(self, **panes: Any) -> None:
        for name in ("summary", "components", "decisions", "checks"):
            self.query_one(f"#view-{name}", Static).update(panes.get(name, ""))
        self.query_one("#review-error", Static).update("")
        self.query_one("#main", ContentSwitcher).current = "results"
        self.query_one("#results", TabbedContent).active = "tab-summary"
        self.query_one("#results Tabs").focus()  # ← → move between the result views
        self._show_step()

    def _plot(self, report) -> None:
        from textual_plotext import PlotextPlot

        box = self.query_one("#plot-box", VerticalScroll)
        box.remove_children()
        figures = views.plots(report)
        for data in figures:
            plot = PlotextPlot()
            plt = plot.plt
            plt.title(data.title)
            plt.xlabel(data.xlabel)
            plt.ylabel(data.ylabel)
            for label, xs, ys in data.series:
                if len(xs) == 1:
                    plt.scatter(xs, ys, label=label)
                else:
                    plt.plot(xs, ys, label=label)
            box.mount(plot)
        self.query_one("#plot-note", Static).update(
            " · ".join(d.title for d in figures)
            + ("  (scroll for more)" if len(figures) > 1 else "")
        )


def run(path: Path | None, catalog_dir: Path | None) -> int:
    """``advisor`` and ``advisor REQ.toml``: the wizard, prefilled from a file if given.

    The file is read like a batch input (:func:`advisor.io_safety.read_toml`); one that
    cannot be read at all is an :class:`InputError` (exit 2, one line); wrong-typed values
    open with the problems shown."""
    doc, problems = None, []
    if path is not None:
        doc, problems, _ = drafts.open_doc(path)
    app = DriveAdvisorApp(doc, path, catalog_dir, problems=problems)
    app.run()
    return 1 if app.return_code else 0
