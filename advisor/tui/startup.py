"""The wizard's start: the first screen painted from the file as read, the rest after it."""

import asyncio
import copy
import threading
import time
from typing import Any

from textual.widgets import (
    Input,
    Label,
    RadioButton,
    Static,
)

from advisor.core import registry
from advisor.core.io_safety import plain, printable, show
from advisor.tui.lazy import drafts, fields, fixes, views
from advisor.tui.screens import ConfirmScreen

#: At most this many loading problems are listed (then how many more).
MAX_PROBLEMS = 8
#: How long the keyboard must be quiet, once the start-up has built what keys need, before
#: the rest of it runs (the warm-up's imports and the result views' layout, ≈ 0.3 s of the
#: one interpreter): keys typed at the first paint are answered first [s].
QUIET_S = 0.1


class StartUp:
    """Mixin of :class:`advisor.tui.app.DriveAdvisorApp`: what the first screen did not need,
    done after its first paint (the document shaped, the draft offered, the engine warmed)."""

    def _init_start(self, warm_up: bool | None) -> None:
        # None: in a terminal, not under a test's Pilot (headless), where it would only cost
        self.warm_up = warm_up
        self._built = asyncio.Event()  # set once every step is built (see _start)
        self._warmed = threading.Event()  # set when the warm-up advice is done (or none)
        self._warmed.set()
        self._warming = False  # the warm-up is on (see _start)
        #: the document the warm-up advised on and its design (None: none, or taken)
        self._warm_advice: tuple[dict[str, Any], Any] | None = None
        self._last_input_s = -1.0  # when the last key, paste or click came (monotonic)

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

    async def _start(self) -> None:
        """What a key needs: the document shaped (tables where tables belong, values of the
        right kind), the draft to offer and the step shown built, before the first paint
        (a few milliseconds). The rest waits until that paint is done and the keys typed
        at it are answered (:meth:`_after_start`)."""
        try:
            await self._build_start()
        finally:
            self._built.set()
        if self.is_headless:  # under a test's Pilot: all of it before the first key
            await self._after_start()
        else:
            self.screen.call_after_refresh(self._after_first_paint)

    def _after_first_paint(self) -> None:
        self._last_input_s = max(self._last_input_s, time.monotonic())
        self._when_quiet()

    def _when_quiet(self) -> None:
        """:meth:`_after_start` once no key, paste or click has come for :data:`QUIET_S`."""
        wait_s = self._last_input_s + QUIET_S - time.monotonic()
        if wait_s > 0:
            self.set_timer(wait_s, self._when_quiet)
        else:
            self.call_later(self._after_start)

    async def _after_start(self) -> None:
        """The warm-up of the engine started in a thread of its own, then the result views
        mounted (a compute that comes first mounts them itself)."""
        warm = self.warm_up if self.warm_up is not None else not self.is_headless
        self._warming = warm
        kind, _ = self._first_look()
        if warm and kind is not None and not self.computing:  # the file as given
            self._warmed.clear()
            doc = copy.deepcopy(self._given)
            threading.Thread(target=self._warm, args=(doc,), daemon=True).start()
        await self._ensure_results()

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

    async def _build_start(self) -> None:
        # any document (a file, a draft, a test's dict) is shaped so that no widget breaks
        doc = self._given
        shaped, found = drafts.shape(copy.deepcopy(doc)) if doc else ({}, [])
        self.doc = shaped
        self.load_problems += found
        if self.kind in fields.titles():
            fixes.fill_fixed(self.doc, self.kind)
        self._last_doc = copy.deepcopy(fields.prune(self.doc))
        # the draft to offer, read before anything could save over it; none saved meanwhile
        if self.offer_draft:
            loaded = drafts.load_draft(self.source)
            if loaded.doc is None and loaded.problems:  # unreadable: set aside, say so
                self.load_problems += loaded.problems
            elif loaded.doc and (
                self.source is None or fields.prune(loaded.doc) != fields.prune(self.doc)
            ):
                self._offered = loaded
        self.query_one("#title-label", Label).update(fields.title_field().label)
        title = self.query_one("#f-application-title", Input)
        shaped_title = printable(str(self.doc.get("application", {}).get("title", "")), False)
        if title.value != shaped_title:
            title.value = shaped_title
        await self._build_steps()
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
            if kind in fields.titles():
                fixes.fill_fixed(self.doc, kind)
            for k in fields.titles():
                self.query_one(f"#kind-{k}", RadioButton).value = k == kind
            self.query_one("#f-application-title", Input).value = app.get("title", "")
            await self._build_steps()
            self._show_step()
            self._show_problems(loaded.problems)
            self._last_doc = None
            self._changed()  # the document resumed is the draft
        else:
            drafts.clear_draft(self.source)
