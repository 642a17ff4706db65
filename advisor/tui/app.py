"""The terminal wizard: requirements step by step, an explained design, export.

It calls exactly the engine the batch uses (:func:`advisor.core.engine.advise`), in a worker
thread so the screen never freezes. Every change is saved to a draft in the user's state
directory and offered back at the next start.

Start-up is staged so that the first screen shows within half a second: the first step is
painted from the file as read (textual and the registry only); the questions, which come
from the pydantic models, the other steps and the result views are built right after that
first paint, keys typed meanwhile waiting (none is lost); then a worker thread imports the
engine and the application and advises once on the file as given, so that the first ctrl+r
finds the modules and catalogs loaded (and, on a file not edited, that design). The plotting
library is loaded after the first results are painted.
"""

import asyncio
import copy
import importlib
import threading
import time
from pathlib import Path
from typing import Any, ClassVar

import tomli_w
from rich.markup import escape
from rich.text import Text
from textual import events, on
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

from advisor.core import registry
from advisor.core.errors import InfeasibleError, InputError
from advisor.core.io_safety import plain, printable, show


class _OnFirstUse:
    """A module imported when first used: the wizard's fields, drafts and views import the
    requirement models (pydantic), which the first screen must not wait for."""

    def __init__(self, name: str) -> None:
        self.__dict__["_name"] = name

    def __getattr__(self, attr: str) -> Any:
        return getattr(importlib.import_module(self._name), attr)


drafts: Any = _OnFirstUse("advisor.tui.draft")
F: Any = _OnFirstUse("advisor.tui.fields")
fixes: Any = _OnFirstUse("advisor.tui.fixes")
views: Any = _OnFirstUse("advisor.tui.views")

#: The asking steps and the review, as :mod:`advisor.tui.fields` numbers them (its STEPS:
#: the application, the registry's default steps, the review); the first screen lays out
#: their places before that module is imported.
_ASKED = tuple(range(1, len(registry.DEFAULT_STEPS) + 1))
_REVIEW = len(registry.DEFAULT_STEPS) + 1

CSS = """
Screen { layout: vertical; }
#steps { height: 1; padding: 0 1; background: $boost; }
#draft-status { height: auto; padding: 0 1; color: $warning; display: none; }
#main { height: 1fr; }
.step { padding: 0 1; }
.field { height: auto; margin: 0; }
.field Vertical { height: auto; width: 1fr; }
.field Label.name { width: 2fr; max-width: 46; padding: 1 1 0 0; }
.field Vertical { width: 3fr; }
.field Input { width: 100%; max-width: 34; }
.field Select { width: 100%; max-width: 34; }
.error { color: $error; height: auto; width: 1fr; padding: 0 0 0 1; }
.fixes { height: auto; }
.fix { height: auto; }
.fix Static { width: 1fr; height: auto; color: $error; padding: 1 1 0 0; }
.fix Button { margin-right: 1; }
.note { color: $text-muted; height: auto; width: 1fr; }
#review-text { height: auto; }
#result-status { height: auto; padding: 0 1; }
#plot-switcher { height: 1fr; }
.plot-pane { height: 1fr; }
.plot-legend { height: auto; padding: 0 1; }
#compare-box Static { height: auto; }
.uses { height: auto; }
.uses Button:focus { text-style: bold reverse; }
.switch-row { height: auto; }
.switch-row Label.state { padding: 1 1; }
ModalScreen { align: center middle; }
#dialog { width: 80; height: auto; border: thick $primary; padding: 1 2; background: $surface; }
#dialog Horizontal { height: auto; margin-top: 1; }
#dialog Button { margin-right: 1; }
PlotextPlot { height: 1fr; min-height: 10; }
"""

HELP = """\
[b]Drive Advisor — keys[/b]

  ctrl+n   next step (waits until the step is valid)
  ctrl+b   previous step (keeps what you typed)
  ctrl+r   compute the design (from any step; again after an edit)
  ctrl+e   back to the inputs from the results (Compare: "Use …"
           imposes an alternative in the requirement and computes it)
  ctrl+s   export the report (TOML, JSON, Markdown or HTML) or
           the requirements
  [ / ]    previous / next plot on the Plot view
  f1       this help           ctrl+q   quit
  enter moves to the next field (on the last one, to the next step);
  tab / shift+tab move between fields; arrows choose in lists; a
  paste of several lines fills field after field, a line each

Nothing is computed or exported while a field shows an error: ctrl+r and
ctrl+s take you to it first.

Every change is saved as a draft (one per file opened, one for a new
requirement) and offered back at the next start.
Numbers are SI with the unit shown beside each field.
"""


#: At most this many loading problems are listed (then how many more).
MAX_PROBLEMS = 8


class SteadyInput(Input):
    """An input whose editing keys act in the order they were typed.

    textual runs a widget's own key bindings (ctrl+u, backspace, arrows, enter) only once
    the key has bubbled up to the app, hop by hop, while a printable key is inserted at once:
    on a loaded machine, or under a fast typist, the characters typed after ctrl+u landed
    first and were then deleted with it (the tmux test lost its export path so). Here the
    input's own bindings run as the key arrives."""

    async def _on_key(self, event: events.Key) -> None:
        bindings = self._bindings.key_to_bindings.get(event.key, [])
        if bindings and not event.is_printable:
            event.stop()
            event.prevent_default()
            await self.run_action(bindings[0].action)
            return
        await super()._on_key(event)


def _input(value: str, id: str) -> Input:
    """An input whose cursor does not blink (a steady screen, and steady snapshots) and
    whose keys act in order (:class:`SteadyInput`)."""
    box = SteadyInput(value, id=id)
    box.cursor_blink = False
    return box


class SteadyFooter(Footer):
    """A footer that rebuilds its keys only when the keys it shows change.

    textual's footer recomposes (a dozen new widgets, restyled) on every change of focus;
    a compute moves the focus several times, and each rebuild cost more than the compute."""

    _shown: Any = None

    def _keys(self) -> tuple[Any, ...]:
        return tuple(
            (binding, enabled, tooltip)
            for (_, binding, enabled, tooltip) in self.screen.active_bindings.values()
            if binding.show
        )

    def bindings_changed(self, screen: Any) -> None:
        self._bindings_ready = True
        if not screen.app.app_focus:
            return
        if self.is_attached and screen is self.screen:
            self.call_after_refresh(self._recompose_if_changed)

    async def _recompose_if_changed(self) -> None:
        if not self.is_attached:
            return
        keys = self._keys()
        if keys != self._shown:
            self._shown = keys
            await self.recompose()


def _steady_key(content: Any) -> Any:
    """What a text shows, to compare (None: a renderable that cannot be compared)."""
    if isinstance(content, str):
        return ("str", content)
    if isinstance(content, Text):
        return ("text", content.plain, tuple(content.spans), str(content.style))
    return None


class _Steady:
    """Mixin: an update with what the widget already shows (text) does nothing; an update
    lays the whole screen out again, and a compute checks every field."""

    _shown: Any = None

    def update(self, content: Any = "", *, layout: bool = True) -> None:
        key = _steady_key(content)
        if key is not None and key == self._shown:
            return
        self._shown = key
        super().update(content, layout=layout)  # type: ignore[misc]


class SteadyStatic(_Steady, Static):
    """A static that ignores an update to what it already shows."""


class SteadyLabel(_Steady, Label):
    """A label that ignores an update to what it already shows."""


class Choice(RadioButton):
    """A radio button whose state reads without colour (NO_COLOR): ● chosen, blank not."""

    @property
    def BUTTON_INNER(self) -> str:  # type: ignore[override]
        return "●" if self.value else " "


def _on_off(value: bool) -> str:
    return "yes" if value else "no"


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
    """Where to write the report (or the requirements). The path box has the focus from the
    start, so nothing typed is lost; enter in it saves (the report where there is one)."""

    BINDINGS: ClassVar = [Binding("escape", "dismiss", "Cancel")]
    AUTO_FOCUS = "#export-path"

    def __init__(self, default: Path, has_report: bool, why_no_report: str = "") -> None:
        super().__init__()
        self.default, self.has_report, self.why_no_report = default, has_report, why_no_report

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Label("Export to (.toml; a report also .json, .md or .html; asks to replace):")
            yield _input(str(self.default), "export-path")
            yield Static(self.why_no_report, id="export-error", classes="error")
            with Horizontal():
                yield Button(
                    "Save report", id="save-report", variant="primary", disabled=not self.has_report
                )
                yield Button("Save requirements", id="save-requirements")
                yield Button("Cancel", id="cancel")

    def on_mount(self) -> None:
        # at once, not after the first paint: keys typed as soon as the dialog shows land here
        self.set_focus(self.query_one("#export-path", Input))

    @on(Button.Pressed, "#cancel")
    def _cancel(self) -> None:
        self.dismiss()

    @on(Input.Submitted, "#export-path")
    def _enter(self) -> None:
        self._save_as("report" if self.has_report else "requirements")

    @on(Button.Pressed, "#save-report, #save-requirements")
    def _save(self, event: Button.Pressed) -> None:
        self._save_as("report" if event.button.id == "save-report" else "requirements")

    def _save_as(self, what: str) -> None:
        box = self.query_one("#export-path", Input)
        text = box.value.strip()
        if not text:
            self.query_one("#export-error", Static).update("give a file name")
            self.set_focus(box)
            return
        path = Path(text).expanduser()
        if what == "requirements" and path.name.endswith(".report.toml"):
            path = path.with_name(path.name.replace(".report.toml", ".toml"))
        problem = self._refusal(path, what)
        if problem:  # said in the dialog, before any question: the path stays to be changed
            self.query_one("#export-error", Static).update(problem)
            self.set_focus(box)
            return
        if path.exists():
            self.app.push_screen(
                ConfirmScreen(f"{show(path, 200)} exists. Replace it?", "Replace", "Keep it"),
                lambda yes: self._write(path, what) if yes else self._kept(),
            )
        else:
            self._write(path, what)

    def _refusal(self, path: Path, what: str) -> str:
        """Why a target is refused, as advisor --batch -o refuses it: the requirement file the
        wizard opened (a report must not replace its input), or an existing target that is
        not a regular file (a directory, a FIFO, a device)."""
        from advisor.core.io_safety import same_file

        source = getattr(self.app, "source", None)
        if what == "report" and source is not None and same_file(source, path):
            return f"{show(path, 200)} is the requirement file itself: choose another name"
        if path.exists() and not path.is_file():
            return f"{show(path, 200)} is not a regular file: choose another name"
        return ""

    def _kept(self) -> None:
        """The existing file stays; the path typed stays too, in the box, to be changed."""
        box = self.query_one("#export-path", Input)
        self.query_one("#export-error", Static).update("not replaced: change the name")
        self.set_focus(box)

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
        self.report = None
        self.previous_report = None
        self.computed_doc: dict[str, Any] | None = None  # the input of the result shown
        self.no_result_why = "nothing computed yet: ctrl+r computes the design"
        self.field_errors: dict[str, str] = {}  # widget id → what its field shows as wrong
        self.fixes: dict[str, fixes.Fix] = {}  # button id → what it does to the document
        self.use_options: dict[str, Any] = {}  # button id → the alternative it imposes
        self.fix_buttons: dict[int, list[Button]] = {}  # step → its fix buttons shown
        self._step_lines: dict[int, list[str]] = {}  # step → the messages shown on it
        self.plot_index = 0
        self.computing = False
        self.results_version = 0
        self.last_compute_s = 0.0
        self._last_doc: Any = None  # the document as last saved (or opened)
        #: why the last draft save failed (None: it worked, or none was tried)
        self.draft_unsaved: str | None = None
        self._offered: Any = None  # the draft offered (a drafts.Loaded), while it is
        # None: in a terminal, not under a test's Pilot (headless), where it would only cost
        self.warm_up = warm_up
        self._built = asyncio.Event()  # set once every step is built (see _start)
        self._warmed = threading.Event()  # set when the warm-up advice is done (or none)
        self._warmed.set()
        self._warming = False  # the warm-up is on (see _start)
        #: the document the warm-up advised on and its design (None: none, or taken)
        self._warm_advice: tuple[dict[str, Any], Any] | None = None
        self._widgets: dict[str, Any] = {}  # id → widget, see _by_id
        self._engine_marked: set[str] = set()  # fields whose label shows an engine message
        self._engine_said: tuple[Any, list[str]] | None = None  # document → its messages
        self._plots_preloaded = False  # the plotting library's import started (or done)
        self._views_report: Any = None  # the report whose plots and comparison are shown
        self._views_version = 0  # counts the results shown
        self._plots_shown = 0  # the _views_version whose plots are built
        self._compare_shown = 0  # the _views_version whose comparison is built
        self._figures: list[Any] = []
        self._plot_panes: set[str] = set()  # the ids of the plot panes mounted
        self._steps_built: set[int] = set()  # the asking steps whose fields are mounted
        self._texts: dict[str, str] = {}  # widget id → its text, for a step not built yet
        self._synced: dict[str, str] = {}  # widget id → the text last put in the document
        self._wrong: dict[str, str] = {}  # widget id → the value set aside, in words
        #: None: every step built at once under a test's Pilot (headless), else on demand
        self.build_all_steps = build_all_steps

    def _first_look(self) -> tuple[str | None, str]:
        """The application and the title the first screen shows, from the document as given
        (before it is shaped: only a registered kind and a text title are shown)."""
        doc = self._given if isinstance(self._given, dict) else {}
        app = doc.get("application")
        app = app if isinstance(app, dict) else {}
        kind = app.get("kind")
        title = app.get("title", "")
        return (
            kind if isinstance(kind, str) and kind in registry.kinds() else None,
            # control and bidi characters escaped: a box that printed them raw would let the
            # title clear or retitle the terminal
            printable(title, newlines=False) if isinstance(title, str) else "",
        )

    # ------------------------------------------------------------------ layout
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
                    yield _input(title, "f-application-title")
                    yield SteadyStatic("", id="step-0-error", classes="error")
                for s in _ASKED:
                    yield VerticalScroll(id=f"step-{s}", classes="step")
                with VerticalScroll(id=f"step-{_REVIEW}", classes="step"):
                    yield SteadyStatic("", id="review-text")
                    yield SteadyStatic("", id="review-error", classes="error")
            yield Vertical(id="results")  # its views are built by _start
        yield SteadyFooter()

    @staticmethod
    def _result_views() -> list[Any]:
        """The result's status line and its views, one tab each."""
        panes = []
        for name in ("Summary", "Components", "Compare", "Decisions", "Checks", "Plot"):
            if name == "Compare":
                children: list[Any] = [VerticalScroll(id="compare-box")]
            elif name == "Plot":
                children = [
                    SteadyStatic("", id="plot-note", classes="note"),
                    ContentSwitcher(id="plot-switcher"),
                ]
            else:
                children = [VerticalScroll(SteadyStatic("", id=f"view-{name.lower()}"))]
            panes.append(TabPane(name, *children, id=f"tab-{name.lower()}"))
        tabs = TabbedContent(id="result-tabs")
        for pane in panes:  # as `with TabbedContent():` adds them
            tabs.compose_add_child(pane)
        return [SteadyStatic("", id="result-status"), tabs]

    async def on_mount(self) -> None:
        if self.build_all_steps is None:
            self.build_all_steps = self.is_headless
        if self.is_headless:  # under a test's Pilot: ready before the first key
            await self._start()
        else:  # in a terminal: the first step is painted first
            self.screen.call_after_refresh(self._start)

    async def on_event(self, event: events.Event) -> None:
        """Keys, clicks and pastes wait (in order) until the start-up is done (_start); keys
        and pastes then act in the order typed (:meth:`_key_in_order`, :meth:`_paste_lines`)."""
        if isinstance(event, events.InputEvent | events.Paste) and not self._built.is_set():
            await self._built.wait()
        if isinstance(event, events.Key) and not event.is_forwarded:
            if await self._key_in_order(event):
                return
        elif isinstance(event, events.Paste) and not event.is_forwarded:
            if await self._paste_lines(event):
                return
        await super().on_event(event)

    async def _settle(self, widget: Any) -> None:
        """Wait until ``widget`` has handled every event already sent to it.

        textual hands a key to the focused widget by queueing it there and goes on with the
        next key at once: in a burst ("600⏎25⏎" from tmux, a paste typed by the terminal, a
        fast typist on a loaded machine) every key was queued in the first box before that
        box handled its enter, and the focus moved only after all of them had landed in it
        (60025 N and an empty stroke). A callback queued behind them runs once they are
        handled (milliseconds); a widget closing meanwhile holds the keys at most 5 s."""
        done = asyncio.Event()
        if widget.is_attached and widget.call_later(done.set):
            try:
                await asyncio.wait_for(done.wait(), timeout=5.0)
            except TimeoutError:
                pass

    def _wizard_box(self) -> Input | None:
        """The wizard's field (a text box) that has the focus, if any (not a dialog's)."""
        box = self.focused
        if isinstance(box, Input) and self._field_by_id(box.id) is not None:
            return box
        return None

    async def _key_in_order(self, event: events.Key) -> bool:
        """A key that moves the focus acts in the order typed (True: it was handled here).

        A printable key goes to the focused box, behind the keys before it (one queue, in
        order). Any other key first waits until the focused box has handled those: a
        binding (ctrl+n, ctrl+r …) then sees the text typed before it. Enter in a wizard's
        field, tab and shift+tab move the focus here and now, before the next key is handed
        on, instead of bubbling up from the box while the keys after them land in it."""
        box = self.focused
        if not isinstance(box, Input) or event.is_printable:
            return False
        await self._settle(box)
        if box is not self.focused:  # (the focus moved meanwhile, as by a click: textual's)
            return False
        self._sync_box(box)
        if event.key == "enter" and self._wizard_box() is box:
            await self._enter_in(box)
            return True
        if event.key in ("tab", "shift+tab") and not self._bindings_for(box, event.key):
            if event.key == "tab":
                self.screen.focus_next()
            else:
                self.screen.focus_previous()
            return True
        return False

    def _sync_box(self, box: Input) -> None:
        """The text of a wizard's field into the document (and the draft) now. Its change
        message is still on its way up, behind the key being handled here: ctrl+q right
        after "25" quit before it arrived, and the draft lacked the 25."""
        f = self._field_by_id(box.id)
        if f is not None and self._synced.get(f.id) != box.value:
            self._sync_input(f, box.value)
            self._changed()

    @staticmethod
    def _bindings_for(box: Input, key: str) -> bool:
        """Whether the box or one of its containers (below the screen) binds ``key``."""
        node: Any = box
        while node is not None and node is not box.screen:
            if node._bindings.key_to_bindings.get(key):
                return True
            node = node.parent
        return False

    async def _paste_lines(self, event: events.Paste) -> bool:
        """A paste of several lines into a wizard's field: each line into the field that
        has the focus, and each line break acts as enter (the next field), as if typed.
        textual's own box keeps the first line only; typed by a terminal without bracketed
        paste, the lines ran together (“6 kN250 mm”). True: it was handled here."""
        text = event.text.replace("\r\n", "\n").replace("\r", "\n")
        if "\n" not in text or self._wizard_box() is None:
            return False
        lines = text.split("\n")
        for i, line in enumerate(lines):
            box = self._wizard_box()
            if box is None:  # the focus left the fields (a fix to make, the review): stop
                break
            if line:
                box._forward_event(events.Paste(line))
                await self._settle(box)
                self._sync_box(box)
            if i < len(lines) - 1:
                await self._enter_in(box)
        return True

    async def _enter_in(self, box: Input) -> None:
        """enter in a wizard's field: the next field; on the step's last one, the next step."""
        step = self.query_one(f"#step-{self.step}")
        chain = [w for w in step.query("Input, Select, Switch") if w.can_focus]
        if box in chain and chain.index(box) < len(chain) - 1:
            self.set_focus(chain[chain.index(box) + 1])
        else:
            await self.action_next()

    async def _start(self) -> None:
        """Everything the first screen did not need: the warm-up of the engine started in
        a worker thread, then the document shaped (tables where tables belong, values of
        the right kind), the draft to offer and the step shown built."""
        warm = self.warm_up if self.warm_up is not None else not self.is_headless
        self._warming = warm
        kind, _ = self._first_look()
        if warm and kind is not None:  # the file as given: as the batch would read it
            self._warmed.clear()
            doc = copy.deepcopy(self._given)
            # a thread of its own, started now (a worker would start once this returns)
            threading.Thread(target=self._warm, args=(doc,), daemon=True).start()
        try:
            await self._build_start()
        finally:
            self._built.set()

    def _warm(self, doc: dict[str, Any]) -> None:
        """Import the engine, the application and its views, and advise once (the result
        discarded): the catalogs are read and cached before the first ctrl+r. Nothing else:
        the plotting library, which only the Plot view needs, is loaded once the first
        results are painted (:meth:`_preload_plots`)."""
        try:
            from advisor.core import engine
            from advisor.core.reading import parse_requirements

            views.plots  # noqa: B018  (the views module and rich's tables)
            kind = doc.get("application", {}).get("kind")
            registry.views(kind)
            registry.pipeline(kind)
            given = copy.deepcopy(doc)
            self._warm_advice = (given, engine.advise(parse_requirements(doc), self.catalog_dir))
        except Exception:  # an invalid or infeasible input: warmed all the same
            pass
        finally:
            self._warmed.set()

    def _preload_plots(self) -> None:
        """Import the plotting library (0.05–0.2 s) in a thread of its own, once, after the
        first results are painted: in the warm-up it ran just as a first ctrl+r computed and
        painted, and delayed that by as much (one interpreter, one core); a Plot view opened
        before it is done imports it itself."""
        if self._plots_preloaded or not self._warming:
            return
        self._plots_preloaded = True

        def load() -> None:
            try:
                import textual_plotext  # noqa: F401
            except ImportError:  # said when a plot is shown
                pass

        threading.Thread(target=load, daemon=True).start()

    async def _build_start(self) -> None:
        # any document (a file, a draft, a test's dict) is shaped so that no widget breaks
        doc = self._given
        shaped, found = drafts.shape(copy.deepcopy(doc)) if doc else ({}, [])
        self.doc = shaped
        self.load_problems += found
        if self.kind in F.titles():
            fixes.fill_fixed(self.doc, self.kind)
        self._last_doc = copy.deepcopy(F.prune(self.doc))
        # the draft to offer, read before anything could save over it; none saved meanwhile
        if self.offer_draft:
            loaded = drafts.load_draft(self.source)
            if loaded.doc is None and loaded.problems:  # unreadable: set aside, say so
                self.load_problems += loaded.problems
            elif loaded.doc and (self.source is None or F.prune(loaded.doc) != F.prune(self.doc)):
                self._offered = loaded
        self.query_one("#title-label", Label).update(F.title_field().label)
        title = self.query_one("#f-application-title", Input)
        shaped_title = printable(str(self.doc.get("application", {}).get("title", "")), False)
        if title.value != shaped_title:
            title.value = shaped_title
        await self._build_steps()
        await self.query_one("#results", Vertical).mount(*self._result_views())
        tabs = self.query_one("#result-tabs", TabbedContent)
        self.watch(tabs, "active", self._show_lazy_views, init=False)
        self._show_step()
        self._show_problems(self.load_problems)
        if self._offered is not None and self._offered.doc:
            saved = self._offered.doc
            kind = saved.get("application", {}).get("kind", "?")
            title = show(saved.get("application", {}).get("title", ""))
            what = (
                f"Unsaved changes to {show(self.source.name)} from your last session were found"
                if self.source is not None
                else "A draft from your last session was found"
            )
            self.push_screen(
                ConfirmScreen(
                    f"{what}: {kind}" + (f", “{title}”" if title else "") + ".\nResume it?",
                    "Resume",
                    "Start fresh" if self.source is None else "Open the file as saved",
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
        loaded, self._offered = self._offered, None
        if yes and loaded is not None and loaded.doc is not None:
            self.doc = loaded.doc
            app = self.doc.get("application", {})
            kind = app.get("kind")
            if kind in F.titles():
                fixes.fill_fixed(self.doc, kind)
            for k in F.titles():
                self.query_one(f"#kind-{k}", RadioButton).value = k == kind
            self.query_one("#f-application-title", Input).value = app.get("title", "")
            await self._build_steps()
            self._show_step()
            self._show_problems(loaded.problems)
            self._last_doc = None
            self._changed()  # the document resumed is the draft
        else:
            drafts.clear_draft(self.source)

    @property
    def kind(self) -> str | None:
        kind = self.doc.get("application", {}).get("kind")
        return kind if isinstance(kind, str) else None

    async def _build_steps(self) -> None:
        """The fields of every step, from the document. In a terminal only the step shown
        is built now, the others when first shown or checked (see :meth:`_ensure_step`):
        building them all costs about 0.4 s, which a first ctrl+r would wait for."""
        kind = self.kind if self.kind in F.titles() else None
        self.field_errors.clear()
        self._steps_built.clear()
        self._texts.clear()
        self._synced.clear()
        self._wrong.clear()
        for s in F.ASKED:
            await self.query_one(f"#step-{s}", VerticalScroll).remove_children()
        if kind is not None:
            # what the fields show is what the document holds, from the first screen on:
            # the text a field shows (:func:`F.to_text`) is put back as it would be read
            for f in F.all_fields(kind):
                if f.kind not in ("bool", "choice"):  # the fields shown in an input box
                    text = self._texts[f.id] = F.to_text(f, F.get(self.doc, f.path))
                    self._sync_input(f, text, quiet=True)
                else:
                    self._set_aside_wrong(f)
        for s in F.ASKED:
            if kind is None or self.build_all_steps or s == self.step:
                await self._build_step(s)

    async def _build_step(self, s: int) -> None:
        kind = self.kind if self.kind in F.titles() else None
        box = self.query_one(f"#step-{s}", VerticalScroll)
        widgets: list[Any] = []
        if kind is None:
            widgets.append(Static("Choose the application first.", classes="note"))
        else:
            note = F.row_note(kind, s)
            if note:
                widgets.append(Static(note, classes="note"))
            for f in F.fields_for(kind, s):
                widgets.append(self._field_widget(f))
        widgets.append(SteadyStatic("", id=f"step-{s}-error", classes="error"))
        widgets.append(Vertical(id=f"step-{s}-fixes", classes="fixes"))
        self._steps_built.add(s)
        await box.mount(*widgets)
        if kind is not None:
            for f in F.fields_for(kind, s):  # the field's own error, if its text has one
                w = self._by_id(f.id)
                if isinstance(w, Input):
                    self._sync_input(f, w.value, quiet=True)

    async def _ensure_step(self, s: int) -> None:
        """Build step ``s`` if it is an asking step not built yet."""
        if s in F.ASKED and s not in self._steps_built:
            await self._build_step(s)

    def _set_aside_wrong(self, f: "F.Field") -> None:
        """A switch or a list cannot show a value it does not offer: the value is set aside
        (the default applies) and its field says so when built (see :meth:`_field_widget`)."""
        value = F.get(self.doc, f.path)
        if value is None:
            return
        if f.kind == "bool" and not isinstance(value, bool):
            self._wrong[f.id] = f"{value!r} in the file is not true or false; shown: the default"
        elif f.kind == "choice" and value not in f.choices:
            self._wrong[f.id] = (
                f"{value!r} in the file is not one of {', '.join(f.choices)}; shown: "
                + ("the default" if f.optional else "the first; choose")
            )
        else:
            return
        F.put(self.doc, f.path, None)

    def _field_widget(self, f: "F.Field") -> Horizontal:
        value = F.get(self.doc, f.path)
        label = f.label + (f" [{f.unit}]" if f.unit else "") + (" (optional)" if f.optional else "")
        wrong = self._wrong.pop(f.id, "")
        if f.kind == "bool":
            on = bool(f.default if value is None else value)
            control: Any = Horizontal(
                Switch(on, id=f.id),
                SteadyLabel(_on_off(on), id=f"{f.id}-state", classes="state"),
                classes="switch-row",
            )
        elif f.kind == "choice":
            blank = f.default is None  # no default to show: the field may stay unchosen
            current = value if value in f.choices else self._shown_choice(f)
            if blank and value not in f.choices:
                current = Select.NULL
            control = Select([(c, c) for c in f.choices], value=current, allow_blank=blank, id=f.id)
        else:
            # the text the document's value showed when read (a step built later: its
            # value may have been refused, and the field shows what was refused)
            text = self._texts.pop(f.id, None)
            control = _input(F.to_text(f, value) if text is None else text, f.id)
            control.placeholder = f.shown_default
        err = SteadyLabel(wrong, id=f"{f.id}-err", classes="error", markup=False)
        return Horizontal(
            Label(label, classes="name", markup=False),
            Vertical(control, err),
            classes="field",
        )

    @staticmethod
    def _shown_choice(f: "F.Field") -> str:
        """The choice shown while the file has none: the model's default."""
        return f.default if f.default in f.choices else f.choices[0]

    # ------------------------------------------------------------------ steps
    def _walk(self) -> list[tuple[int, str]]:
        return F.steps_for(self.kind if self.kind in F.titles() else None)

    def _step_bar(self, width: int) -> str:
        walk = self._walk()

        def bar(level: int) -> str:
            """0: every name; 1: first words; 2: numbers only, the current step and Review
            named."""
            out = []
            for i, (s, name) in enumerate(walk):
                if s == self.step:
                    out.append(f"[reverse] {i + 1} {name} [/]")
                elif level == 0 or s == F.REVIEW:
                    out.append(f"{i + 1} {name}")
                elif level == 1:
                    out.append(f"{i + 1} {name.split()[0]}")
                else:
                    out.append(f"{i + 1}")
            return " › ".join(out)

        for level in (0, 1):
            text = bar(level)
            if len(Text.from_markup(text).plain) <= width - 2:
                return text
        return bar(2)

    def _show_step(self, focus: bool = True) -> None:
        on_results = self.query_one("#main", ContentSwitcher).current == "results"
        if self.computing:
            text = "[reverse] Computing… [/] the design of the inputs shown"
        elif on_results:
            text = "[reverse] Results [/] ← → views · ctrl+e inputs · ctrl+s export"
        else:
            text = self._step_bar(self.size.width or 80)
        self.query_one("#steps", Static).update(text)
        self.query_one("#wizard", ContentSwitcher).current = f"step-{self.step}"
        if self.step == F.REVIEW:
            self.query_one("#review-text", Static).update(self._review_text())
        if focus and not on_results:
            self._focus_step()

    def on_resize(self) -> None:
        if self.is_mounted and self._built.is_set():
            self._show_step(focus=False)

    def _focus_step(self, target: Any = None) -> None:
        """Focus ``target`` or the first field of the step shown: keys typed next land there."""
        if target is None:
            box = self.query_one(f"#step-{self.step}")
            if self.step == 0:
                target = self.query_one("#kind", RadioSet)
            else:
                target = next(
                    (w for w in box.query("Input, Select, Switch, Button") if w.can_focus), None
                )
        if target is not None:
            if target.is_mounted:
                self.set_focus(target)
            else:  # just mounted (a fix button): focus it once it is
                target.call_after_refresh(self.set_focus, target)

    def _review_text(self) -> str:
        from rich.markup import escape

        text = tomli_w.dumps(F.prune(self.doc)) if self.doc else "(nothing yet)"
        return "[b]Review — the requirement as it will be computed (ctrl+r):[/b]\n\n" + escape(text)

    # ------------------------------------------------------------------ editing
    def _field_by_id(self, wid: str | None) -> "F.Field | None":
        if wid == "f-application-title":
            return F.title_field()
        kind = self.kind
        if kind not in F.titles() or wid is None:
            return None
        return next((f for f in F.all_fields(kind) if f.id == wid), None)

    def _changed(self) -> None:
        now = F.prune(self.doc)
        if now == self._last_doc:  # a widget reporting what it already showed: no change
            return
        self._last_doc = copy.deepcopy(now)
        if self.save_drafts and self._offered is None:  # not while a draft is being offered
            self._save_draft()
        if self.report is not None:
            self._show_result_status()

    def _save_draft(self) -> None:
        """Save the draft; when it cannot be (its directory is a file, read-only, full …),
        say so once, as a notice and on the status line under the steps, and keep the input
        in memory: a notice at every keystroke would bury the screen. The line stays while
        the saves fail, and goes at the first save that works again."""
        try:
            drafts.save_draft(F.prune(self.doc), self.source)
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

    def _sync_input(self, f: "F.Field", text: str, quiet: bool = False) -> str | None:
        """Put what a field shows into the document: its value, or nothing while it shows an
        error (what is computed is exactly what the fields show). ``quiet``: an empty field
        says nothing yet (a new requirement is not all "required")."""
        self._synced[f.id] = text
        value, err = F.parse_text(f, text)
        if not text.strip():  # empty: the engine says whether it is required (its table may
            err = None  # be optional, as a duty cycle is) and marks the field if so
        F.put(self.doc, f.path, value if err is None else None)
        was = self.field_errors.pop(f.id, None)
        if err is not None:
            self.field_errors[f.id] = err
        label = self._by_id(f"{f.id}-err")
        # an empty field keeps what the engine said of it ("missing; required"), unless it
        # showed an error of its own text
        if label is not None and (err is not None or text.strip() or was is not None):
            label.update(plain(err or ""))
        return err

    @on(RadioSet.Changed, "#kind")
    async def _kind_changed(self, event: RadioSet.Changed) -> None:
        kind = (event.pressed.id or "").removeprefix("kind-")
        if kind == self.kind or not self._built.is_set():  # (not the first screen's own)
            return
        keep = {k: v for k, v in self.doc.get("application", {}).items() if k != "kind"}
        self.doc = {"application": {"kind": kind, **keep}, **F.starting_doc(kind)}
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
            if F.get(self.doc, f.path) is not None:
                F.put(self.doc, f.path, None)
                self._changed()
            return
        if F.get(self.doc, f.path) is None and event.value == self._shown_choice(f):
            return  # the shown default, not a choice the user made: keep the file as it was
        F.put(self.doc, f.path, event.value)
        self.query_one(f"#{f.id}-err", Label).update("")
        self._changed()

    @on(Switch.Changed)
    def _switch_changed(self, event: Switch.Changed) -> None:
        f = self._field_by_id(event.switch.id)
        if f is not None:
            F.put(self.doc, f.path, bool(event.value))
            self.query_one(f"#{f.id}-state", Label).update(_on_off(bool(event.value)))
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

    # ------------------------------------------------------------------ validation
    def _validate(self, step: int) -> bool:
        """Field errors of the step, then the engine's own validation of what is known so
        far; messages about later steps wait for those steps. A message no field resolves
        comes with buttons that do (remove or rename an unknown key …)."""
        if step == 0:
            if self.kind is None:
                self.query_one("#step-0-error", Static).update("choose an application")
                return False
            return True
        if step == F.REVIEW:
            return True
        kind = self.kind
        assert kind is not None
        if step not in self._steps_built:
            # not built yet: its fields would show the document (see _build_steps), so the
            # field errors are known, and the engine's messages tell the rest
            return not any(f.id in self.field_errors for f in F.fields_for(kind, step)) and all(
                F.error_owner(line, kind, step) is None for line in self._engine_errors()
            )
        ok = True
        for f in F.fields_for(kind, step):
            w = self._by_id(f.id)
            if isinstance(w, Input):
                ok = self._sync_input(f, w.value) is None and ok
            elif f.id in self.field_errors:
                ok = False
        step_msgs: list[str] = []
        said: set[str] = set()  # the fields of this step the engine speaks of now
        for line in self._engine_errors():
            owner = F.error_owner(line, kind, step)
            if owner is None:
                continue
            target = next(
                (f for s in range(1, step + 1) for f in F.fields_for(kind, s) if f.dotted == owner),
                None,
            )
            if owner and target is not None and target in F.fields_for(kind, step):
                if target.id not in self.field_errors:  # the field's own words come first
                    self._by_id(f"{target.id}-err").update(plain(line.split(": ", 1)[-1]))
                    said.add(target.id)
            else:
                step_msgs.append(line)
            ok = False
        # what the engine said of a field and says no more goes (an S4's "starts_per_hour:
        # missing" once the duty is S3); a field's own error stays
        for f in F.fields_for(kind, step):
            if f.id in self._engine_marked and f.id not in said and f.id not in self.field_errors:
                label = self._by_id(f"{f.id}-err")
                if label is not None:
                    label.update("")
        self._engine_marked = (
            self._engine_marked - {f.id for f in F.fields_for(kind, step)}
        ) | said
        self._show_step_messages(step, step_msgs)
        return ok

    def _show_step_messages(self, step: int, lines: list[str]) -> None:
        plain_lines, rows = [], []
        for line in lines:
            found = fixes.fixes_for(line, self.doc, self.kind)
            if not found:
                plain_lines.append(line)
                continue
            buttons = []
            for fix in found:
                bid = f"fix-{len(self.fixes)}"
                self.fixes[bid] = fix
                buttons.append(Button(fix.label, id=bid, compact=True))
            row = Horizontal(Static(line, markup=False), *buttons, classes="fix")
            row.fix_buttons = buttons  # type: ignore[attr-defined]
            rows.append(row)
        self.query_one(f"#step-{step}-error", Static).update(plain("\n".join(plain_lines)))
        if lines == self._step_lines.get(step):
            return  # the same messages: keep the rows (and the focus on their buttons)
        self._step_lines[step] = lines
        self.fix_buttons[step] = [b for r in rows for b in r.fix_buttons]
        box = self.query_one(f"#step-{step}-fixes", Vertical)
        box.remove_children()
        if rows:
            box.mount(*rows)

    def _engine_errors(self) -> list[str]:
        """The engine's messages on the document as it is (kept for the same document:
        ctrl+r and ctrl+n validate every step against one document)."""
        from advisor.core.reading import parse_requirements

        doc = F.prune(self.doc)
        if self._engine_said is not None and self._engine_said[0] == doc:
            return list(self._engine_said[1])
        try:
            parse_requirements(copy.deepcopy(doc))
            said: list[str] = []
        except InputError as exc:
            said = exc.messages
        self._engine_said = (copy.deepcopy(doc), said)
        return list(said)

    def _by_id(self, wid: str) -> Any:
        """The widget with id ``wid`` (None: none): found once, then kept while it stays in
        the DOM. Each ``query_one`` walks the DOM, and validating every field at each ctrl+r
        that way cost about 20 ms of the keystroke's latency."""
        w = self._widgets.get(wid)
        if w is None or not w.is_attached or w.id != wid:
            w = self.query_one_optional(f"#{wid}")
            if w is None:
                self._widgets.pop(wid, None)
                return None
            self._widgets[wid] = w
        return w

    def _first_problem(self) -> int | None:
        """The first step (in the order walked) with an error on screen, checked the way
        ctrl+n checks it; None when every step is valid."""
        for s, _ in self._walk():
            if not self._validate(s):
                return s
        return None

    async def _go_to_problem(self, step: int, doing: str) -> None:
        """Show the step with the problem and focus what needs fixing."""
        self.query_one("#main", ContentSwitcher).current = "wizard"
        self.step = step
        if step in F.ASKED and step not in self._steps_built:
            await self._build_step(step)
            self._validate(step)  # its messages, now that it has its fields
        self._show_step(focus=False)
        box = self.query_one(f"#step-{step}")
        target = None
        if step == 0:
            target = self.query_one("#kind", RadioSet)
        else:
            # a fix offered (an unknown key) often explains the field errors: it comes first
            target = next(iter(self.fix_buttons.get(step, [])), None)
            for lbl in box.query(".field Label.error") if target is None else []:
                if str(lbl.render()).strip():
                    wid = (lbl.id or "").removesuffix("-err")
                    target = self.query_one(f"#{wid}")
                    break
        self._focus_step(target)
        self.bell()
        self.notify(f"{doing}: fix what is marked first", severity="warning")

    # ------------------------------------------------------------------ actions
    async def action_next(self) -> None:
        if self.query_one("#main", ContentSwitcher).current == "results":
            return
        if not self._validate(self.step):
            self.bell()
            await self._go_to_problem(self.step, "Not yet")
            return
        walk = [s for s, _ in self._walk()]
        if self.step < F.REVIEW:
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

    def _inputs_changed(self) -> bool:
        return self.computed_doc is not None and F.prune(self.doc) != self.computed_doc

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
            text = tomli_w.dumps(F.prune(self.doc))
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
        doc = copy.deepcopy(F.prune(self.doc))
        self.run_worker(lambda: self._advise(doc), thread=True, exclusive=True, group="advise")

    def _advise(self, doc: dict[str, Any]) -> None:
        self._warmed.wait()  # the warm-up is importing what this needs: let it finish
        from advisor.core.engine import advise
        from advisor.core.reading import parse_requirements

        # the warm-up advised on the file as given: if that is exactly the document to
        # compute (the first ctrl+r on an unedited file), its design is the one (the same
        # function on the same input), taken once
        warm, self._warm_advice = self._warm_advice, None
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

    def _done(self) -> None:
        self.computing = False
        self.last_compute_s = time.perf_counter() - self._started
        self.results_version += 1
        self._show_step(focus=False)
        self.call_after_refresh(self._preload_plots)  # once the results are painted

    def _invalid(self, messages: list[str]) -> None:
        self.step = F.REVIEW
        self.query_one("#main", ContentSwitcher).current = "wizard"
        self._show_step()
        self.query_one("#review-error", Static).update(
            plain("The requirement is not complete or not valid:\n" + "\n".join(messages))
        )
        self._done()

    def _infeasible(self, exc: InfeasibleError, doc: dict[str, Any]) -> None:
        if self.report is not None:
            self.previous_report = self.report
        self.report = None
        self.computed_doc = doc
        self.no_result_why = "the requirement has no feasible design (see Summary)"
        none = f"No design to show: {self.no_result_why}."
        self._fill(
            summary=views.infeasible(exc),
            components=none,
            decisions=none,
            checks=none,
        )
        self._views_of(None)
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

    def _show_report(self, report, doc: dict[str, Any]) -> None:
        if self.report is not None:
            self.previous_report = self.report
        self.report = report
        self.computed_doc = doc
        self._fill(
            summary=views.summary(report, self.previous_report),
            components=views.components(report),
            decisions=views.decisions(report),
            checks=views.checks(report),
        )
        self._views_of(report)
        self._done()

    def _views_of(self, report) -> None:
        """The plots and the comparison of ``report`` (None: of no design) are built when
        their view is shown: a compute paints the summary only."""
        self._views_report = report
        self._views_version += 1
        if report is None:  # no design: said at once, in both views (it costs nothing)
            self._ensure_plots()
            self._compare_shown = self._views_version
            self._compare(None)
        else:  # the previous design's plots and alternatives go at once, shown or not
            self.query_one("#plot-switcher", ContentSwitcher).remove_children()
            self.query_one("#compare-box", VerticalScroll).remove_children()
        self._show_lazy_views()

    def _show_lazy_views(self, *_: Any) -> None:
        active = self.query_one("#result-tabs", TabbedContent).active
        if active == "tab-plot":
            self._ensure_plots()
        elif active == "tab-compare" and self._compare_shown != self._views_version:
            self._compare_shown = self._views_version
            self._compare(self._views_report)

    def _ensure_plots(self) -> None:
        if self._plots_shown != self._views_version:
            self._plots_shown = self._views_version
            self._plot(self._views_report)

    def _compare(self, report) -> None:
        """The alternatives side by side, each with a button that imposes it."""
        box = self.query_one("#compare-box", VerticalScroll)
        box.remove_children()
        self.use_options.clear()
        if report is None:
            box.mount(Static(f"Nothing to compare: {self.no_result_why}.", classes="note"))
            return
        sections = views.compare(report)
        if not sections:
            box.mount(Static("This application reports no alternatives.", classes="note"))
            return
        widgets: list[Any] = []
        for sec in sections:
            widgets.append(Static(Text(sec.title, style="bold underline")))
            widgets.append(Static(sec.table))
            if sec.why:
                widgets.append(Static(Text.assemble(("▶ chosen: ", "bold"), plain(sec.why))))
            if sec.note:
                widgets.append(Static(sec.note, classes="note", markup=False))
            buttons = []
            for opt in sec.options:
                bid = f"use-{self.results_version}-{len(self.use_options)}"
                self.use_options[bid] = opt
                buttons.append(Button(opt.label, id=bid, compact=True, classes="use"))
            if buttons:  # one per line: a row of long labels runs off a narrow screen
                widgets.append(Vertical(*buttons, classes="uses"))
            widgets.append(Static(""))
        box.mount(*widgets)

    @on(Button.Pressed, ".use")
    async def _use_pressed(self, event: Button.Pressed) -> None:
        """Impose the alternative in the requirement, and compute it."""
        opt = self.use_options.get(event.button.id or "")
        if opt is None:
            return
        for path, value in opt.patch:
            F.put(self.doc, path, value)
        self._changed()
        self._step_lines.clear()
        await self._build_steps()
        self.notify(f"{opt.label}: imposed in the requirement; computing", markup=False)
        await self.action_compute()

    def _show_result_status(self) -> None:
        if self.report is None:
            text = f"[b]No design.[/b] {escape(self.no_result_why)}"
        elif self._inputs_changed():
            text = "[reverse] ! [/] The inputs changed since this result: ctrl+r recomputes."
        else:
            text = "The design of the inputs as they are now."
        self.query_one("#result-status", Static).update(text)

    def _fill(self, **panes: Any) -> None:
        for name in ("summary", "components", "decisions", "checks"):
            self.query_one(f"#view-{name}", Static).update(panes.get(name, ""))
        self.query_one("#review-error", Static).update("")
        self.query_one("#main", ContentSwitcher).current = "results"
        self.query_one("#result-tabs", TabbedContent).active = "tab-summary"
        self.query_one("#result-tabs Tabs").focus()  # ← → move between the result views
        self.last_compute_s = time.perf_counter() - self._started
        self._show_result_status()
        self._show_step(focus=False)

    def _plot(self, report) -> None:
        switcher = self.query_one("#plot-switcher", ContentSwitcher)
        switcher.remove_children()
        self._plot_panes.clear()  # (their ids carry the old plot_version)
        self._figures = views.plots(report) if report is not None else []
        self.plot_titles = [d.title for d in self._figures]
        self.plot_index = 0
        self.plot_version = self._views_version
        if not self._figures:
            self.query_one("#plot-note", Static).update(f"No plot: {self.no_result_why}.")
            return
        self._show_plot()

    def _show_plot(self) -> None:
        """The plot ``plot_index`` on screen, drawn the first time it is shown."""
        from textual_plotext import PlotextPlot

        switcher = self.query_one("#plot-switcher", ContentSwitcher)
        pane_id = f"plot-{self.plot_version}-{self.plot_index}"  # old panes go asynchronously
        if pane_id not in self._plot_panes:
            data = self._figures[self.plot_index]
            plot = PlotextPlot()
            plt = plot.plt
            plt.xlabel(data.xlabel)
            plt.ylabel(data.ylabel)
            if data.bars:  # plotext draws the first bar at the bottom: the top one last
                labels, values = zip(*reversed(data.bars), strict=True)
                plt.bar(list(labels), list(values), orientation="horizontal", width=0.4)
                plt.xlim(-1.0, 1.0)
            for marker, (_label, xs, ys) in zip(views.markers(data), data.series, strict=True):
                if len(xs) == 1:
                    plt.scatter(xs, ys, marker=marker)
                else:
                    plt.plot(xs, ys, marker=marker)
            legend = Static(views.legend(data), classes="plot-legend")
            pane = Vertical(legend, plot, id=pane_id, classes="plot-pane")
            pane.display = False
            self._plot_panes.add(pane_id)
            switcher.mount(pane)
        switcher.current = pane_id  # (the switcher shows it once mounted)
        self._plot_note()

    def _plot_note(self) -> None:
        n = len(self.plot_titles)
        title = self.plot_titles[self.plot_index]
        more = f"  ([ ] plot {self.plot_index + 1} of {n})" if n > 1 else ""
        self.query_one("#plot-note", Static).update(f"[b]{escape(title)}[/b]{more}")

    def action_plot(self, step: int) -> None:
        if self._views_version:
            self._ensure_plots()
        n = len(getattr(self, "plot_titles", []))
        if n < 2:
            return
        self.plot_index = (self.plot_index + step) % n
        self._show_plot()


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
