"""Keys and pastes acting in the order typed, whatever the machine's load."""

import asyncio
import time
from typing import Any

from textual import events
from textual.widgets import (
    Input,
)


class KeysInOrder:
    """Mixin of :class:`advisor.tui.app.DriveAdvisorApp`: a key that moves the focus acts in
    the order typed, and a paste of several lines fills field after field."""

    async def on_event(self, event: events.Event) -> None:
        """Keys, clicks and pastes wait (in order) until the start-up is done (_start); keys
        and pastes then act in the order typed (:meth:`_key_in_order`, :meth:`_paste_lines`)."""
        if isinstance(event, events.Key | events.Paste | events.MouseDown):
            self._last_input_s = time.monotonic()  # (the start-up's rest waits for quiet)
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
