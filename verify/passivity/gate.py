"""`verify gate`: the passivity check a lab runs in CI on new human models (Section 4).

Every model file is validated before any is analysed (bad input fails fast and whole).
A passive verdict writes its exactly checked KYP certificate under the certificates
directory (with ``--band W1:W2``, a generalized KYP certificate for that band, see
:mod:`verify.passivity.band`), naming its model file by a path relative to that
directory, so ``verify certificates check`` finds the file from the certificate wherever
it runs; a JSON summary and a JUnit XML file (one test case per model) are optional.
In the command's batch, a model on which the tool itself fails gets an ``error`` result
(its own line, JSON entry and JUnit ``<error>``) and the other models keep theirs.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

from verify.artefacts.atomic import OutputError, write_atomic
from verify.errors import VerifyInputError
from verify.inputs.number_text import unlimited_int_text
from verify.inputs.numbers import parse_number
from verify.passivity.check.fd_certificate import PrCertificate
from verify.passivity.decision import PASSIVE, Decision, decide
from verify.passivity.io import certificate_files as cf
from verify.passivity.io.binding import (
    PERTURBED_SUFFIX,
    Claim,
    Perturbed,
    relative_source,
    shifted,
    unverified_meta,
)
from verify.passivity.search.canonical import coarse_band, coarse_kyp
from verify.passivity.search.tolerance import PASSIVE_WITHIN, within_tolerance
from verify.passivity.verdicts import INCONCLUSIVE
from verify.progress import silent


def parse_margin(text: str) -> Fraction:
    """A margin nu0 as an exact rational ("1e-8", "0.01", "1/100"); one-line error otherwise.

    A decimal denotes the decimal it spells, as in model files."""
    return parse_number(text, "--margin", "--margin 1e-8 or --margin 1/100")


def parse_tolerance(text: str) -> Fraction:
    """--tolerance EPS as an exact rational >= 0 ("1e-12", "0"); one-line error otherwise."""
    value = parse_number(text, "--tolerance", "--tolerance 1e-12")
    if value < 0:
        raise VerifyInputError(f"--tolerance {text!r} is negative; it is a relative "
                               "distance >= 0 (0 = exact)")
    return value


@dataclass
class GateResult:
    decision: Decision
    certificate_path: Path | None
    indices: tuple | None = None  # (IFP, OFP) IndexBounds when asked for
    kept: bool = False  # the certificate file already held a valid one of the same claim
    error: str | None = None  # the tool failed on this model (a bug): no verdict
    #: What checked the verdict (``coq``, ``exact-python``, ``not-exported: reason``) and
    #: the Coq theorem stating it; set by ``verify gate`` (``--coq`` compiles the units).
    kernel: str | None = None
    coq_theorem: str | None = None
    #: For a passive verdict with a KYP certificate under ``--coq``: the Coq theorem of
    #: Theorem 1 with this human in the loop, when coqc accepted it.
    coq_closed_loop_theorem: str | None = None

    @property
    def passed(self) -> bool:
        return self.error is None and self.decision.verdict in (PASSIVE, PASSIVE_WITHIN)

    def line(self) -> str:
        with unlimited_int_text():  # a reason may hold exact numbers of any size
            return self._line()

    def _line(self) -> str:
        d = self.decision
        if self.error is not None:
            return (f"ERROR {d.model.name} ({d.model.source}, {d.model.n} states, "
                    f"{d.seconds:.2f} s): no verdict: {self.error}")
        head = f"{'PASS' if self.passed else 'FAIL'} {d.model.name} ({d.model.source}, " \
               f"{d.model.n} states, {d.seconds:.2f} s): {d.verdict}"
        perturbation = getattr(d, "perturbation", None)
        kept = " (kept: already a valid certificate of this model and claim)" \
            if self.kept else ""
        if perturbation is not None:
            text = (f"{head}: {perturbation.summary()}; certificate of the perturbed model "
                    f"{self.certificate_path}{kept}")
        elif self.passed:
            text = f"{head}; certificate {self.certificate_path}{kept}"
        else:
            text = f"{head}; {d.reason}"
        if self.passed and d.note:  # a non-minimal realisation: say what was decided
            text += f"; {d.note}"
        for index in self.indices or ():
            text += f"\n  {index.summary()}"
        return text


def store_pr_certificate(cert: PrCertificate, margin: Fraction,
                         certificates_dir: Path) -> tuple[Path, bool]:
    """Write a frequency-domain certificate under the name its claim asks for; a file that
    already holds a valid certificate of the same model and claim is kept."""
    from verify.passivity.check import fd_certificate as fd
    from verify.passivity.io.binding import file_name
    from verify.passivity.io.certificate_files import dumps, keep_or_write

    data = dict(cert.to_json(), meta={"margin": str(Fraction(margin))})
    data["source"] = relative_source(data["source"], certificates_dir)
    given = shifted(cert.model, -Fraction(margin))
    path = Path(certificates_dir) / file_name(cert.name, Claim(Fraction(margin)),
                                              given.fingerprint())

    def still_valid(old: Path) -> bool:
        stored = fd.parse_json_text(old.read_text())
        return (stored.get("fingerprint") == data["fingerprint"]
                and fd.check_pr_file(stored, old).ok)

    return keep_or_write(path, dumps(data), still_valid)


def run_gate(models, margin: Fraction, certificates_dir: Path,
             tolerance: Fraction = Fraction(0), *, keep_going: bool = False,
             stage: Callable[[str], None] = silent) -> list[GateResult]:
    """Decide each model; with ``tolerance`` > 0 a model that is not passive as written may
    pass as *passive within tolerance* (:mod:`verify.passivity.search.tolerance`), and then the
    certificate written is the perturbed model's (it names that model exactly). With
    ``keep_going`` (the command's batch), an internal error on one model is that model's
    ``error`` result (:func:`guarded`) instead of an exception. ``stage`` is told which
    model is being decided (progress lines)."""
    with unlimited_int_text():  # exact numbers of any size from here (inputs validated)
        results = []
        for k, model in enumerate(models):
            stage(_deciding(k, len(models), model))
            results.append(_each(model, lambda m=model: _gate_one(
                m, margin, certificates_dir, tolerance, stage), keep_going))
        return results


def _deciding(k: int, count: int, model) -> str:
    return f"deciding model {k + 1} of {count}: {model.name} ({model.n} states, {model.m} " \
        "port(s))"


def _each(model, work: Callable[[], GateResult], keep_going: bool) -> GateResult:
    return guarded(model, work) if keep_going else work()


#: At most this many characters of an internal error's message are kept in a result.
ERROR_TEXT_LIMIT = 300


def guarded(model, work: Callable[[], GateResult]) -> GateResult:
    """``work()`` on one model of a batch; an internal error (a bug of the tool) becomes
    this model's ``error`` result instead of ending the batch, so the other models keep
    their verdicts. An output that cannot be written still ends the call (exit 2)."""
    start = time.perf_counter()
    try:
        return work()
    except OutputError:
        raise
    except Exception as exc:
        text = " ".join(f"{type(exc).__name__}: {exc}".split())
        if len(text) > ERROR_TEXT_LIMIT:
            text = text[:ERROR_TEXT_LIMIT] + " ..."
        d = Decision(model, INCONCLUSIVE, f"internal error of the tool: {text}",
                     seconds=time.perf_counter() - start)
        return GateResult(d, None, error=text)


def _gate_one(model, margin: Fraction, certificates_dir: Path,
              tolerance: Fraction, stage: Callable[[str], None] = silent) -> GateResult:
    d = decide(model, margin, stage=stage)
    if tolerance:
        d = within_tolerance(model, tolerance, margin, d)
    path, kept = None, False
    if isinstance(d.certificate, PrCertificate):  # the frequency-domain route
        path, kept = store_pr_certificate(d.certificate, margin, certificates_dir)
    elif d.certificate is not None:
        claim = Claim(Fraction(margin))
        H = shifted(d.certificate.model, -claim.margin)  # the model as given
        P = coarse_kyp(d.certificate.model, d.certificate.P)
        source = relative_source(model.source, certificates_dir)
        perturbation = getattr(d, "perturbation", None)
        if perturbation is None:
            name, meta, perturbed = model.name, unverified_meta(model), None
        else:  # bound to the file's model and (a, d), re-derived when checked
            name, meta = model.name + PERTURBED_SUFFIX, unverified_meta(model)
            perturbed = Perturbed(perturbation.shift, perturbation.feedthrough)
        path, kept = cf.store_certificate(
            cf.kyp_json(name, source, H, claim, P, meta, perturbed), certificates_dir)
    return GateResult(d, path, kept=path is not None and kept)


def run_band_gate(models, band: tuple[Fraction, Fraction], margin: Fraction,
                  certificates_dir: Path, *, exact_first: bool = True,
                  keep_going: bool = False,
                  stage: Callable[[str], None] = silent) -> list[GateResult]:
    """The gate on a finite band: exact band or generalized KYP certificates (written), or
    witnesses (``exact_first``: see :func:`verify.passivity.band.decide_band`;
    ``keep_going`` as for :func:`run_gate`)."""
    from verify.passivity.band import decide_band
    from verify.passivity.check.band_fd import BandFdCertificate

    def one(model) -> GateResult:
        d = decide_band(model, band, margin, exact_first=exact_first)
        if isinstance(d.certificate, BandFdCertificate):  # the exact band route
            cert = replace(d.certificate,
                           source=relative_source(d.certificate.source, certificates_dir))
            path, kept = cf.store_band_fd_certificate(cert, certificates_dir)
            return GateResult(d, path, kept=kept)
        return _band_one(d, model, band, margin, certificates_dir)

    results = []
    with unlimited_int_text():
        for k, model in enumerate(models):
            stage(_deciding(k, len(models), model))
            results.append(_each(model, lambda m=model: one(m), keep_going))
    return results


def _band_one(d, model, band: tuple[Fraction, Fraction], margin: Fraction,
              certificates_dir: Path) -> GateResult:
    path, kept = None, False
    if d.certificate is not None:
        claim = Claim(Fraction(margin), band)
        H = shifted(d.certificate.model, -claim.margin)  # the model as given
        P, Q = coarse_band(d.certificate.model, d.certificate.P, d.certificate.Q, band)
        path, kept = cf.store_certificate(cf.band_json(
            model.name, relative_source(model.source, certificates_dir), H, claim, P, Q,
            unverified_meta(model)), certificates_dir)
    return GateResult(d, path, kept=path is not None and kept)


def add_indices(results: list[GateResult], stage: Callable[[str], None] = silent) -> None:
    """Attach the passivity indices nu_IFP and rho_OFP (estimates and exact bounds)."""
    from verify.passivity.indices import indices

    with unlimited_int_text():
        for r in results:
            if r.error is not None:
                continue
            stage(f"passivity indices of {r.decision.model.name}")
            found = guarded(r.decision.model, lambda r=r: replace(
                r, indices=indices(r.decision.model)))
            if found.error is not None:
                r.error = found.error
            else:
                r.indices = found.indices


def json_text(results: list[GateResult]) -> str:
    """The JSON summary (one entry per model; a model the tool failed on has the verdict
    "error" and the error's text)."""
    with unlimited_int_text():  # exact numbers of any size, written in full
        return json.dumps([_json_entry(r) for r in results], indent=2) + "\n"


def _json_entry(r: GateResult) -> dict:
    if r.error is not None:
        d = r.decision
        return {"name": d.model.name, "source": d.model.source, "verdict": "error",
                "reason": d.reason, "error": r.error, "seconds": round(d.seconds, 4),
                "passed": False, "certificate": None, **_kernel_json(r)}
    return {**r.decision.to_json(), "passed": r.passed,
            "certificate": None if r.certificate_path is None else str(r.certificate_path),
            **_kernel_json(r),
            **({} if r.indices is None else {
                "indices": {i.kind: i.to_json() for i in r.indices}})}


def _kernel_json(r: GateResult) -> dict:
    return {} if r.kernel is None else {"kernel": r.kernel, "coq_theorem": r.coq_theorem,
                                        "coq_closed_loop_theorem": r.coq_closed_loop_theorem}


def write_json(results: list[GateResult], path: Path) -> None:
    write_atomic(path, json_text(results))


@dataclass(frozen=True)
class JunitCase:
    """One test case of a JUnit report: a model (or claim) and its outcome."""

    classname: str
    name: str
    file: str
    seconds: float
    passed: bool
    verdict: str
    reason: str
    #: Properties of the case (e.g. its kernel status), written as JUnit <properties>.
    properties: tuple[tuple[str, str], ...] = ()


def junit_text(cases: list[JunitCase], suite: str = "passivity gate") -> str:
    """JUnit XML of ``cases`` (one <testcase> each; a failure carries the reason)."""
    errors = sum(c.verdict == "error" for c in cases)  # the tool failed: no verdict
    failures = sum(not c.passed for c in cases) - errors
    total = sum(c.seconds for c in cases)
    lines = []
    for c in cases:
        tag = "error" if c.verdict == "error" else "failure"
        body = "" if c.passed else (
            f"<{tag} message={quoteattr(c.verdict + ': ' + c.reason)}>"
            f"{escape(c.reason)}</{tag}>"
        )
        props = "".join(f"<property name={quoteattr(k)} value={quoteattr(v)}/>"
                        for k, v in c.properties)
        if props:
            body = f"<properties>{props}</properties>{body}"
        lines.append(
            f'  <testcase classname="{c.classname}" name={quoteattr(c.name)} '
            f'file={quoteattr(c.file)} time="{c.seconds:.4f}">{body}</testcase>'
        )
    return (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        f'<testsuite name={quoteattr(suite)} tests="{len(cases)}" failures="{failures}" '
        f'errors="{errors}" time="{total:.4f}">\n' + "\n".join(lines) + "\n</testsuite>\n"
    )


def gate_cases(results: list[GateResult]) -> list[JunitCase]:
    """The JUnit cases of gate results (classname ``verify.gate``)."""
    return [JunitCase("verify.gate", r.decision.model.name, r.decision.model.source,
                      r.decision.seconds, r.passed,
                      "error" if r.error is not None else str(r.decision.verdict),
                      r.decision.reason, _kernel_properties(r))
            for r in results]


def _kernel_properties(r: GateResult) -> tuple[tuple[str, str], ...]:
    if r.kernel is None:
        return ()
    return (("kernel", r.kernel),) + ((("coq_theorem", r.coq_theorem),)
                                      if r.coq_theorem else ()) + (
        (("coq_closed_loop_theorem", r.coq_closed_loop_theorem),)
        if r.coq_closed_loop_theorem else ())


def write_junit(results: list[GateResult], path: Path) -> None:
    write_atomic(path, junit_text(gate_cases(results)))
