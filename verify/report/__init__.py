"""Reports rendered from the claim registry (Markdown, HTML, JSON), written atomically."""

from __future__ import annotations

from pathlib import Path

from verify.artefacts.atomic import write_all_atomic, write_atomic
from verify.claims.runner import RunResult
from verify.report.render import render_html, render_json, render_markdown
from verify.report.run_info import RUN_RECORD, write_run_record

REPORT_FILES = ("report.md", "report.html", "report.json")
APPENDIX_FILE = "appendix.tex"
SUPPLEMENT_FILE = "supplement.tex"


def write_report(run: RunResult, out_dir: Path, *, latex: bool = False) -> list[Path]:
    """Render every format in memory first, then write each file atomically; with
    ``latex`` also ``appendix.tex`` (:mod:`verify.report.latex`)."""
    out_dir = Path(out_dir)
    rendered = {
        out_dir / "report.md": render_markdown(run),
        out_dir / "report.html": render_html(run),
        out_dir / "report.json": render_json(run),
    }
    if latex:
        from verify.report.latex import render_latex, render_supplement

        rendered[out_dir / APPENDIX_FILE] = render_latex(run)
        rendered[out_dir / SUPPLEMENT_FILE] = render_supplement(run)
    write_all_atomic(rendered)
    return list(rendered)


__all__ = [
    "APPENDIX_FILE",
    "REPORT_FILES",
    "RUN_RECORD",
    "SUPPLEMENT_FILE",
    "write_atomic",
    "write_report",
    "write_run_record",
]
