"""The run record: when ``verify all`` ran and how long each check took.

A report is a function of the code, the inputs and the seed; the clock time and the
timings are not, so they are kept out of every report (Markdown, HTML, JSON, LaTeX) and
written instead to a separate JSON file, ``build/run.json`` by default (git-ignored), and
to standard output. A committed report therefore stays byte-identical when ``verify all``
runs again, with no environment variable to set.
"""

from __future__ import annotations

import json
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from verify.artefacts.atomic import write_atomic
from verify.claims.runner import RunResult

#: Where ``verify all`` records its date and timings unless told otherwise.
RUN_RECORD = Path("build") / "run.json"

RUN_SCHEMA = "verify-run/1"


def run_record(run: RunResult, *, generated: datetime | None = None,
               reports: list[Path] | None = None) -> dict[str, Any]:
    """The date, the total time and each claim's time of one run (never in a report)."""
    when = (generated or datetime.now(UTC)).isoformat(timespec="seconds")
    return {"schema": RUN_SCHEMA, "generated": when, "seed": run.seed,
            "seconds": round(run.seconds, 3),
            "timings": {r.claim.id: round(r.seconds, 4) for r in run.results},
            "reports": [str(p) for p in reports or ()]}


def write_run_record(run: RunResult, path: Path = RUN_RECORD, *,
                     reports: list[Path] | None = None) -> Path:
    """Write :func:`run_record` to ``path`` atomically; returns the path."""
    text = json.dumps(run_record(run, reports=reports), indent=2) + "\n"
    write_atomic(Path(path), text.encode())
    return Path(path)


__all__ = ["RUN_RECORD", "RUN_SCHEMA", "run_record", "write_run_record"]
