"""Where to write the report or the requirements, refused as the batch refuses a target."""

from pathlib import Path
from typing import Any, ClassVar

from textual import on
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Static

from advisor.core.errors import InputError
from advisor.core.io_safety import plain, show
from advisor.tui.screens.confirm import ConfirmScreen
from advisor.tui.widgets import steady_input


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
            yield steady_input(str(self.default), "export-path")
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
        app: Any = self.app  # the wizard: it writes what it holds (write_export)
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
