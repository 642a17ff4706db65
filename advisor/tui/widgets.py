"""The wizard's widgets: textual's own, made steady (keys in the order typed, no update
that changes nothing, a footer rebuilt only when its keys change) and readable without colour."""

from typing import Any

from rich.text import Text
from textual import events
from textual.app import ComposeResult
from textual.widgets import Footer, Input, Label, RadioButton, Static


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


def steady_input(value: str, id: str) -> Input:
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

    def compose(self) -> ComposeResult:
        # the keys in the first paint: built after it, the rebuild (a dozen widgets, styled)
        # ran just when a key pressed at that paint was to be answered
        self._bindings_ready = True
        self._shown = self._keys()
        yield from super().compose()

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


def on_off(value: bool) -> str:
    """A switch's state in words, beside it."""
    return "yes" if value else "no"
