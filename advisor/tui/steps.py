"""The wizard's steps: their fields built from the document, the step bar, the focus."""

from typing import Any

import tomli_w
from rich.markup import escape
from rich.text import Text
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.widgets import (
    Button,
    ContentSwitcher,
    Input,
    Label,
    RadioSet,
    Select,
    Static,
    Switch,
)

from advisor.tui.lazy import fields
from advisor.tui.widgets import SteadyLabel, SteadyStatic, on_off, steady_input


class StepPages:
    """Mixin of :class:`advisor.tui.app.DriveAdvisorApp`: each asking step's fields, built
    from the document when first shown, and the step shown."""

    def _init_steps(self, build_all_steps: bool | None) -> None:
        self.field_errors: dict[str, str] = {}  # widget id → what its field shows as wrong
        self.fixes: dict[str, Any] = {}  # button id → the Fix it applies to the document
        self.fix_buttons: dict[int, list[Button]] = {}  # step → its fix buttons shown
        self._step_lines: dict[int, list[str]] = {}  # step → the messages shown on it
        self._widgets: dict[str, Any] = {}  # id → widget, see _by_id
        self._engine_marked: set[str] = set()  # fields whose label shows an engine message
        self._engine_said: tuple[Any, list[str]] | None = None  # document → its messages
        self._steps_built: set[int] = set()  # the asking steps whose fields are mounted
        self._texts: dict[str, str] = {}  # widget id → its text, for a step not built yet
        self._synced: dict[str, str] = {}  # widget id → the text last put in the document
        self._wrong: dict[str, str] = {}  # widget id → the value set aside, in words
        #: None: every step built at once under a test's Pilot (headless), else on demand
        self.build_all_steps = build_all_steps

    @property
    def kind(self) -> str | None:
        kind = self.doc.get("application", {}).get("kind")
        return kind if isinstance(kind, str) else None

    async def _build_steps(self) -> None:
        """The fields of every step, from the document. In a terminal only the step shown
        is built now, the others when first shown or checked (see :meth:`_ensure_step`):
        building them all costs about 0.4 s, which a first ctrl+r would wait for."""
        kind = self.kind if self.kind in fields.titles() else None
        self.field_errors.clear()
        self._steps_built.clear()
        self._texts.clear()
        self._synced.clear()
        self._wrong.clear()
        for s in fields.ASKED:
            await self.query_one(f"#step-{s}", VerticalScroll).remove_children()
        if kind is not None:
            # what the fields show is what the document holds, from the first screen on:
            # the text a field shows (:func:`fields.to_text`) is put back as it would be read
            for f in fields.all_fields(kind):
                if f.kind not in ("bool", "choice"):  # the fields shown in an input box
                    text = self._texts[f.id] = fields.to_text(f, fields.get(self.doc, f.path))
                    self._sync_input(f, text, quiet=True)
                else:
                    self._set_aside_wrong(f)
        for s in fields.ASKED:
            if kind is None or self.build_all_steps or s == self.step:
                await self._build_step(s)

    async def _build_step(self, s: int) -> None:
        kind = self.kind if self.kind in fields.titles() else None
        box = self.query_one(f"#step-{s}", VerticalScroll)
        widgets: list[Any] = []
        if kind is None:
            widgets.append(Static("Choose the application first.", classes="note"))
        else:
            note = fields.row_note(kind, s)
            if note:
                widgets.append(Static(note, classes="note"))
            for f in fields.fields_for(kind, s):
                widgets.append(self._field_widget(f))
        widgets.append(SteadyStatic("", id=f"step-{s}-error", classes="error"))
        widgets.append(Vertical(id=f"step-{s}-fixes", classes="fixes"))
        self._steps_built.add(s)
        await box.mount(*widgets)
        if kind is not None:
            for f in fields.fields_for(kind, s):  # the field's own error, if its text has one
                w = self._by_id(f.id)
                if isinstance(w, Input):
                    self._sync_input(f, w.value, quiet=True)

    async def _ensure_step(self, s: int) -> None:
        """Build step ``s`` if it is an asking step not built yet."""
        if s in fields.ASKED and s not in self._steps_built:
            await self._build_step(s)

    def _set_aside_wrong(self, f: "fields.Field") -> None:
        """A switch or a list cannot show a value it does not offer: the value is set aside
        (the default applies) and its field says so when built (see :meth:`_field_widget`)."""
        value = fields.get(self.doc, f.path)
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
        fields.put(self.doc, f.path, None)

    def _field_widget(self, f: "fields.Field") -> Horizontal:
        value = fields.get(self.doc, f.path)
        label = f.label + (f" [{f.unit}]" if f.unit else "") + (" (optional)" if f.optional else "")
        wrong = self._wrong.pop(f.id, "")
        if f.kind == "bool":
            on = bool(f.default if value is None else value)
            control: Any = Horizontal(
                Switch(on, id=f.id),
                SteadyLabel(on_off(on), id=f"{f.id}-state", classes="state"),
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
            control = steady_input(fields.to_text(f, value) if text is None else text, f.id)
            control.placeholder = f.shown_default
        err = SteadyLabel(wrong, id=f"{f.id}-err", classes="error", markup=False)
        return Horizontal(
            Label(label, classes="name", markup=False),
            Vertical(control, err),
            classes="field",
        )

    @staticmethod
    def _shown_choice(f: "fields.Field") -> str:
        """The choice shown while the file has none: the model's default."""
        return f.default if f.default in f.choices else f.choices[0]

    def _walk(self) -> list[tuple[int, str]]:
        return fields.steps_for(self.kind if self.kind in fields.titles() else None)

    def _step_bar(self, width: int) -> str:
        walk = self._walk()

        def bar(level: int) -> str:
            """0: every name; 1: first words; 2: numbers only, the current step and Review
            named."""
            out = []
            for i, (s, name) in enumerate(walk):
                if s == self.step:
                    out.append(f"[reverse] {i + 1} {name} [/]")
                elif level == 0 or s == fields.REVIEW:
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
        if self.step == fields.REVIEW:
            self.query_one("#review-text", Static).update(self._review_text())
        if focus and not on_results:
            self._focus_step()

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

        text = tomli_w.dumps(fields.prune(self.doc)) if self.doc else "(nothing yet)"
        return "[b]Review — the requirement as it will be computed (ctrl+r):[/b]\n\n" + escape(text)
