"""The result views: summary, components, compare, decisions, checks and plots."""

import asyncio
import threading
import time
from typing import Any

from rich.markup import escape
from rich.text import Text
from textual.containers import Vertical, VerticalScroll
from textual.widgets import (
    Button,
    ContentSwitcher,
    Static,
    TabbedContent,
    TabPane,
)

from advisor.core.errors import InfeasibleError
from advisor.core.io_safety import plain
from advisor.tui.lazy import fields, views
from advisor.tui.widgets import SteadyStatic


class ResultViews:
    """Mixin of :class:`advisor.tui.app.DriveAdvisorApp`: a compute's outcome shown in the
    result views; plots and the comparison built when their view is first shown."""

    def _init_results(self) -> None:
        self.report = None
        self.previous_report = None
        self.computed_doc: dict[str, Any] | None = None  # the input of the result shown
        self.no_result_why = "nothing computed yet: ctrl+r computes the design"
        self.use_options: dict[str, Any] = {}  # button id → the alternative it imposes
        self.plot_index = 0
        self.computing = False
        self.results_version = 0
        self.last_compute_s = 0.0
        self._plots_preloaded = False  # the plotting library's import started (or done)
        self._views_report: Any = None  # the report whose plots and comparison are shown
        self._views_version = 0  # counts the results shown
        self._plots_shown = 0  # the _views_version whose plots are built
        self._compare_shown = 0  # the _views_version whose comparison is built
        self._figures: list[Any] = []
        self._plot_panes: set[str] = set()  # the ids of the plot panes mounted
        self._results_asked = False  # the result views' mount has begun
        self._results_ready = asyncio.Event()  # set once they are mounted

    async def _ensure_results(self) -> None:
        """The result views mounted, once: by the start-up once the first keys are answered,
        or by a compute that comes before (see :meth:`_after_start`)."""
        if self._results_asked:
            await self._results_ready.wait()
            return
        self._results_asked = True
        await self.query_one("#results", Vertical).mount(*self._result_views())
        tabs = self.query_one("#result-tabs", TabbedContent)
        self.watch(tabs, "active", self._show_lazy_views, init=False)
        self._results_ready.set()

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

    def _inputs_changed(self) -> bool:
        return self.computed_doc is not None and fields.prune(self.doc) != self.computed_doc

    def _done(self) -> None:
        self.computing = False
        self.last_compute_s = time.perf_counter() - self._started
        self.results_version += 1
        self._show_step(focus=False)
        self.call_after_refresh(self._preload_plots)  # once the results are painted

    def _invalid(self, messages: list[str]) -> None:
        self.step = fields.REVIEW
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
        box.can_focus = True
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
        # with "Use" buttons, tab goes from the view's tabs straight to the first of them (a
        # focused box shows no mark, so the first tab seemed to go nowhere); arrows still
        # scroll the box from a button. Without buttons the box takes the focus to scroll.
        box.can_focus = not self.use_options
        box.mount(*widgets)

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
