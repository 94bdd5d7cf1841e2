"""``verify coq`` and ``verify gate --coq``: write a Coq development, optionally compile it.

``verify coq`` with no file writes the paper's development (the derivation units when
installed, and every exportable certificate of ``certificates/``) to
``certificates/coq/``; with files or folders, the development of those certificates.
``--check`` compiles it with ``coqc`` in a temporary copy (the folder keeps only
sources), prints each file's time, and audits it (:mod:`verify.coq.audit`).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path

from verify.coq.audit import audit_assumptions, forbidden_commands, template_problems
from verify.coq.development import (
    WORD_THEOREMS,
    CompileResult,
    check_files,
    coqc_available,
    prelude_sources,
    render_development,
    write_development,
)
from verify.coq.export import (
    EXPORTED_SCHEMAS,
    PAPER_SOS_REFUSED,
    Export,
    export_certificates,
    not_exported_json,
    paper_development_units,
    schema_of,
)
from verify.errors import VerifyInputError

NOT_EXPORTED_FILE = "NOT_EXPORTED.json"
INSTALL_HINT = "apt-get install coq libcoq-stdlib"


def development_files(export: Export) -> dict[str, str]:
    """Every file of the development of ``export`` (sources, project, the list left out)."""
    return render_development(export.units,
                              extra={NOT_EXPORTED_FILE: not_exported_json(export.not_exported,
                                                                export.partly)})


def write_export(folder: Path, export: Export) -> None:
    write_development(folder, export.units,
                      extra={NOT_EXPORTED_FILE: not_exported_json(export.not_exported,
                                                                export.partly)})


def development_files_of(units) -> dict[str, str]:
    """Every file of a development of ``units`` alone (no list of files left out)."""
    return render_development(units)


def check_and_audit(files: dict[str, str], jobs: int = 1, *, timeout_seconds: float = 600.0
                    ) -> tuple[CompileResult, list[str]]:
    """Compile the files with coqc (``jobs`` units at a time); the audit's problems
    (empty when all is well): forbidden commands, commands outside the templates, and
    axioms beyond Coq's real numbers."""
    result = check_files(files, jobs=jobs, timeout_seconds=timeout_seconds)
    prelude = [f"{name}.v" for name in prelude_sources()]
    problems = [f"forbidden command {f}" for f in forbidden_commands(files)]
    problems += template_problems(files, skip=prelude)
    if result.ok:
        words = f"Print Assumptions {WORD_THEOREMS}." in files.get("All.v", "")
        audit = audit_assumptions(result.output, word_block=words)
        problems += [f"axiom not allowed: {a}" for a in audit.disallowed]
    return result, problems


def _report_check(result: CompileResult, problems: list[str]) -> bool:
    if result.prelude:
        print(f"coq: {result.prelude}")
    for rel, seconds in result.timings:
        failed = rel == result.failed_file
        print(f"{'FAILED' if failed else 'ok    '} {rel} ({seconds:.1f} s)")
    if not result.ok:
        tail = [ln for ln in result.output.splitlines() if ln.strip()][-6:]
        print("coqc: " + "\n      ".join(tail))
    for p in problems:
        print(f"audit: {p}")
    if result.ok and not problems:
        print("coqc accepted every file; no Admitted/admit/Axiom; Print Assumptions lists "
              "only Coq's real-number axioms and excluded middle (and, for the KYP units "
              "checked on machine integers, Coq's primitive integers)")
    return result.ok and not problems


def _same_folder(a: Path, b: Path) -> bool:
    try:
        return Path(a).resolve() == Path(b).resolve()
    except OSError:
        return False


def _input_problem(inputs: Sequence[Path], out: Path) -> str | None:
    """Why the named inputs cannot be exported (one line), or None."""
    for p in inputs:
        p = Path(p)
        if not p.exists():
            return f"no such file or folder: {p}"
        folder = p if p.is_dir() else p.parent
        if _same_folder(folder, out):
            return (f"--out {out} holds the input {p}; write the development to another "
                    "folder")
        if p.is_file() and not schema_of(p):
            return f"{p}: not a certificate file (JSON with a 'schema' field)"
    return None


def run_coq(inputs: Sequence[Path], out: Path | None, check: bool,
            certificates_dir: Path = Path("certificates"), *, jobs: int = 1) -> int:
    """The ``verify coq`` command; returns the exit code."""
    if check and not coqc_available():
        print(f"verify: coqc not found (on Debian/Ubuntu: {INSTALL_HINT})", file=sys.stderr)
        return 2
    if inputs:
        problem = _input_problem(inputs, out or Path("build/coq"))
        if problem:
            print(f"verify: {problem}", file=sys.stderr)
            return 2
        export = export_certificates(list(inputs))
        folder = out or Path("build/coq")
    else:
        if out is not None and _same_folder(out, certificates_dir):
            print(f"verify: --out {out} is the certificates folder; write the development "
                  "elsewhere (default: its coq/ subfolder)", file=sys.stderr)
            return 2
        export = paper_development_units(certificates_dir)
        folder = out or certificates_dir / "coq"
    try:
        files = development_files(export)
        write_export(folder, export)
    except OSError as exc:
        print(f"verify: cannot write {folder}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except ValueError as exc:  # the audit refused it, or two units share a name
        print(f"verify: {exc}; nothing written", file=sys.stderr)
        return 1
    print(f"wrote {folder}: {len(export.units)} unit(s), {len(export.not_exported)} file(s) "
          f"not exported (reasons in {folder / NOT_EXPORTED_FILE})")
    refused = [i for i in export.not_exported
               if i.schema in EXPORTED_SCHEMAS or i.reason.startswith(PAPER_SOS_REFUSED)]
    for item in refused:
        print(f"not exported: {item.reason}")
    ok = not refused
    if check:
        ok = _report_check(*check_and_audit(files, jobs)) and ok
    return 0 if ok else 1


def write_paper_development(certificates_dir: Path) -> str:
    """``verify all``'s last step: the paper's development in ``certificates_dir/coq``
    (not compiled here); returns the line to print. Nothing is written when the run
    wrote no certificate folder (a partial run elsewhere)."""
    if not Path(certificates_dir).is_dir():
        return f"coq: {certificates_dir} does not exist; no Coq development written"
    export = paper_development_units(certificates_dir)
    folder = Path(certificates_dir) / "coq"
    try:
        write_export(folder, export)
    except ValueError as exc:  # the audit refused it, or two units share a name
        return f"coq: {exc}; nothing written"
    return (f"coq: wrote {folder} ({len(export.units)} unit(s); 'verify coq --check' "
            "compiles it)")


def gate_development(certificate_paths: Sequence[Path], folder: Path) -> bool:
    """``verify gate --coq DIR``: the development of the gate's certificates; compiled when
    coqc is installed. Prints one line per step; False when coqc rejected it."""
    export = export_certificates(list(certificate_paths))
    try:
        write_export(folder, export)
    except OSError as exc:
        raise VerifyInputError(f"cannot write {folder}: {exc.strerror or exc}") from None
    except ValueError as exc:  # the audit refused it, or two units share a name
        print(f"coq: {exc}; nothing written")
        return False
    print(f"coq: wrote {folder} ({len(export.units)} unit(s))")
    for item in export.not_exported:
        print(f"coq: {item.file} not exported: {item.reason}")
    for item in export.partly:
        print(f"coq: {item.file} exported in part: {item.reason}")
    if not export.units:
        print("coq: no unit, nothing compiled")
        return True
    if not coqc_available():
        print(f"coq: coqc not found, not compiled ({INSTALL_HINT})")
        return True
    result, problems = check_and_audit(development_files(export))
    if result.ok and not problems:
        print(f"coq: {result.prelude}")
        total = sum(s for _, s in result.timings)
        files = ", ".join(f"{rel} {s:.1f} s" for rel, s in result.timings)
        print(f"coq: compiled by coqc, accepted: {files} ({total:.1f} s)")
        return True
    _report_check(result, problems)
    return False
