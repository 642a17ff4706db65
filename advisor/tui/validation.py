"""What a field shows, checked as it is typed and by the engine before a step is left."""

import copy
from typing import Any

from textual.containers import Horizontal, Vertical
from textual.widgets import (
    Button,
    ContentSwitcher,
    Input,
    RadioSet,
    Static,
)

from advisor.core.errors import InputError
from advisor.core.io_safety import plain
from advisor.tui.lazy import fields, fixes


class StepChecks:
    """Mixin of :class:`advisor.tui.app.DriveAdvisorApp`: each field's text into the document,
    and the errors of a step (its fields' own, then the engine's) with the fixes offered."""

    def _field_by_id(self, wid: str | None) -> "fields.Field | None":
        if wid == "f-application-title":
            return fields.title_field()
        kind = self.kind
        if kind not in fields.titles() or wid is None:
            return None
        return next((f for f in fields.all_fields(kind) if f.id == wid), None)

    def _sync_input(self, f: "fields.Field", text: str, quiet: bool = False) -> str | None:
        """Put what a field shows into the document: its value, or nothing while it shows an
        error (what is computed is exactly what the fields show). ``quiet``: an empty field
        says nothing yet (a new requirement is not all "required")."""
        self._synced[f.id] = text
        value, err = fields.parse_text(f, text)
        if not text.strip():  # empty: the engine says whether it is required (its table may
            err = None  # be optional, as a duty cycle is) and marks the field if so
        fields.put(self.doc, f.path, value if err is None else None)
        was = self.field_errors.pop(f.id, None)
        if err is not None:
            self.field_errors[f.id] = err
        label = self._by_id(f"{f.id}-err")
        # an empty field keeps what the engine said of it ("missing; required"), unless it
        # showed an error of its own text
        if label is not None and (err is not None or text.strip() or was is not None):
            label.update(plain(err or ""))
        return err

    def _validate(self, step: int) -> bool:
        """Field errors of the step, then the engine's own validation of what is known so
        far; messages about later steps wait for those steps. A message no field resolves
        comes with buttons that do (remove or rename an unknown key …)."""
        if step == 0:
            if self.kind is None:
                self.query_one("#step-0-error", Static).update("choose an application")
                return False
            return True
        if step == fields.REVIEW:
            return True
        kind = self.kind
        assert kind is not None
        if step not in self._steps_built:
            # not built yet: its fields would show the document (see _build_steps), so the
            # field errors are known, and the engine's messages tell the rest
            own = any(f.id in self.field_errors for f in fields.fields_for(kind, step))
            return not own and self._engine_quiet_on(kind, step)
        ok = True
        for f in fields.fields_for(kind, step):
            w = self._by_id(f.id)
            if isinstance(w, Input):
                ok = self._sync_input(f, w.value) is None and ok
            elif f.id in self.field_errors:
                ok = False
        step_msgs, said = self._engine_on_step(kind, step)
        self._unmark_engine(kind, step, said)
        self._show_step_messages(step, step_msgs)
        return ok and self._engine_quiet_on(kind, step)

    def _engine_quiet_on(self, kind: str, step: int) -> bool:
        """Whether the engine says nothing that belongs to ``step``."""
        return all(fields.error_owner(line, kind, step) is None for line in self._engine_errors())

    def _engine_on_step(self, kind: str, step: int) -> tuple[list[str], set[str]]:
        """The engine's messages that belong to ``step``: each said on its field's label when
        the field is on this step (and has no error of its own text); the rest, the step's
        own lines. Returns those lines and the ids of the fields marked."""
        step_msgs: list[str] = []
        said: set[str] = set()  # the fields of this step the engine speaks of now
        for line in self._engine_errors():
            owner = fields.error_owner(line, kind, step)
            if owner is None:
                continue
            target = next(
                (
                    f
                    for s in range(1, step + 1)
                    for f in fields.fields_for(kind, s)
                    if f.dotted == owner
                ),
                None,
            )
            if owner and target is not None and target in fields.fields_for(kind, step):
                if target.id not in self.field_errors:  # the field's own words come first
                    self._by_id(f"{target.id}-err").update(plain(line.split(": ", 1)[-1]))
                    said.add(target.id)
            else:
                step_msgs.append(line)
        return step_msgs, said

    def _unmark_engine(self, kind: str, step: int, said: set[str]) -> None:
        """What the engine said of a field and says no more goes (an S4's "starts_per_hour:
        missing" once the duty is S3); a field's own error stays."""
        for f in fields.fields_for(kind, step):
            if f.id in self._engine_marked and f.id not in said and f.id not in self.field_errors:
                label = self._by_id(f"{f.id}-err")
                if label is not None:
                    label.update("")
        self._engine_marked = (
            self._engine_marked - {f.id for f in fields.fields_for(kind, step)}
        ) | said

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

        doc = fields.prune(self.doc)
        if self._engine_said is None or self._engine_said[0] != doc:
            try:
                parse_requirements(copy.deepcopy(doc))
                said: list[str] = []
            except InputError as exc:
                said = exc.messages
            self._engine_said = (copy.deepcopy(doc), said)
        return [out for line in self._engine_said[1] for out in self._named(line)]

    def _named(self, line: str) -> list[str]:
        """A table the engine calls missing only because each of its fields shows an error
        of its own text (none reached the document): those fields, each with its error."""
        table = fixes.message_path(line)
        bad = [
            f
            for f in (fields.all_fields(self.kind) if self.kind in fields.titles() else [])
            if f.id in self.field_errors and f.path[: len(table)] == table
        ]
        if not bad or ": missing" not in line or not table:
            return [line]
        return [f"{f.dotted}: {self.field_errors[f.id]}" for f in bad]

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
        if step in fields.ASKED and step not in self._steps_built:
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
