"""TUI recompute latency: from the key (ctrl+r after an edit) to the updated results, through
textual's Pilot, for each example. Medians over repeated edits."""

import asyncio
import os
import statistics
import tempfile
import time
import tomllib

from _results import examples


async def _one(example, repeats: int) -> dict:
    from textual.widgets import Input

    from advisor.tui.app import DriveAdvisorApp

    app = DriveAdvisorApp(
        tomllib.loads(example.read_text(encoding="utf-8")),
        example,
        save_drafts=False,
        offer_draft=False,
    )
    times = []
    async with app.run_test(size=(120, 40)) as pilot:
        for k in range(repeats + 1):
            # an edit: the title changes (the engine recomputes everything from the inputs)
            app.query_one("#f-application-title", Input).value = f"what-if {k}"
            await pilot.pause()
            start, seen = time.perf_counter(), app.results_version
            await pilot.press("ctrl+r")
            while app.results_version == seen:
                await asyncio.sleep(0.001)
            await pilot.pause()  # the results are on screen
            if k:  # the first one warms the caches
                times.append(time.perf_counter() - start)
    return {"median_ms": 1e3 * statistics.median(times), "max_ms": 1e3 * max(times)}


def tui_latency(repeats: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["XDG_STATE_HOME"] = tmp
        return {ex.name: asyncio.run(_one(ex, repeats)) for ex in examples()}


if __name__ == "__main__":
    for name, r in tui_latency(10).items():
        print(f"{name}: {r['median_ms']:.1f} ms median, {r['max_ms']:.1f} ms max")
