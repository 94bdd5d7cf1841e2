"""`verify gate`: the passivity check a lab runs in CI on new human models (issue 4, item 7).

Every model file is validated before any is analysed (bad input fails fast and whole).
A passive verdict writes its exactly checked KYP certificate under the certificates
directory (with ``--band W1:W2``, a generalized KYP certificate for that band, see
:mod:`verify.passivity.band`); a JSON summary and a JUnit XML file (one test case per
model) are optional.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

from verify.errors import VerifyInputError
from verify.passivity.certificate import write_certificate
from verify.passivity.decide import PASSIVE, Decision, decide
from verify.passivity.tolerance import PASSIVE_WITHIN, within_tolerance
from verify.report.atomic import write_atomic


def parse_margin(text: str) -> Fraction:
    """A margin nu0 as an exact rational ("1e-8", "0.01", "1/100"); one-line error otherwise."""
    try:
        value = Fraction(text.strip())
    except (ValueError, ZeroDivisionError):
        raise VerifyInputError(f"--margin {text!r} is not a finite number") from None
    return value


def parse_tolerance(text: str) -> Fraction:
    """--tolerance EPS as an exact rational >= 0 ("1e-12", "0"); one-line error otherwise."""
    try:
        value = Fraction(str(text).strip())
    except (ValueError, ZeroDivisionError):
        raise VerifyInputError(f"--tolerance {text!r} is not a finite number "
                               "(e.g. --tolerance 1e-12)") from None
    if value < 0:
        raise VerifyInputError(f"--tolerance {text!r} is negative; it is a relative "
                               "distance >= 0 (0 = exact)")
    return value


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "-", name).strip("-") or "model"


@dataclass
class GateResult:
    decision: Decision
    certificate_path: Path | None
    indices: tuple | None = None  # (IFP, OFP) IndexBounds when asked for

    @property
    def passed(self) -> bool:
        return self.decision.verdict in (PASSIVE, PASSIVE_WITHIN)

    def line(self) -> str:
        d = self.decision
        head = f"{'PASS' if self.passed else 'FAIL'} {d.model.name} ({d.model.source}, " \
               f"{d.model.n} states, {d.seconds:.2f} s): {d.verdict}"
        perturbation = getattr(d, "perturbation", None)
        if perturbation is not None:
            text = (f"{head}: {perturbation.summary()}; certificate of the perturbed model "
                    f"{self.certificate_path}")
        elif self.passed:
            text = f"{head}; certificate {self.certificate_path}"
        else:
            text = f"{head}; {d.reason}"
        for index in self.indices or ():
            text += f"\n  {index.summary()}"
        return text


def run_gate(models, margin: Fraction, certificates_dir: Path,
             tolerance: Fraction = Fraction(0)) -> list[GateResult]:
    """Decide each model; with ``tolerance`` > 0 a model that is not passive as written may
    pass as *passive within tolerance* (:mod:`verify.passivity.tolerance`), and then the
    certificate written is the perturbed model's (it names that model exactly)."""
    results = []
    for model in models:
        d = decide(model, margin)
        if tolerance:
            d = within_tolerance(model, tolerance, margin, d)
        path = None
        if d.certificate is not None:
            tag = d.certificate.model.fingerprint()[:12]
            path = certificates_dir / f"{_slug(model.name)}-{tag}.json"
            write_certificate(d.certificate, path)
        results.append(GateResult(d, path))
    return results


def run_band_gate(models, band: tuple[Fraction, Fraction], margin: Fraction,
                  certificates_dir: Path) -> list[GateResult]:
    """The gate on a finite band: generalized KYP certificates (written) or witnesses."""
    from verify.passivity.band import decide_band
    from verify.passivity.gkyp import write_band_certificate

    results = []
    for model in models:
        d = decide_band(model, band, margin)
        path = None
        if d.certificate is not None:
            tag = d.certificate.model.fingerprint()[:12]
            label = f"band-{float(band[0]):.6g}-{float(band[1]):.6g}"
            path = certificates_dir / f"{_slug(model.name)}-{label}-{tag}.json"
            write_band_certificate(d.certificate, path)
        results.append(GateResult(d, path))
    return results


def add_indices(results: list[GateResult]) -> None:
    """Attach the passivity indices nu_IFP and rho_OFP (estimates and exact bounds)."""
    from verify.passivity.indices import indices

    for r in results:
        r.indices = indices(r.decision.model)


def write_json(results: list[GateResult], path: Path) -> None:
    data = [
        {**r.decision.to_json(), "passed": r.passed,
         "certificate": None if r.certificate_path is None else str(r.certificate_path),
         **({} if r.indices is None else {
             "indices": {i.kind: i.to_json() for i in r.indices}})}
        for r in results
    ]
    write_atomic(path, json.dumps(data, indent=2) + "\n")


def write_junit(results: list[GateResult], path: Path) -> None:
    failures = sum(not r.passed for r in results)
    total = sum(r.decision.seconds for r in results)
    cases = []
    for r in results:
        d = r.decision
        body = "" if r.passed else (
            f"<failure message={quoteattr(d.verdict + ': ' + d.reason)}>"
            f"{escape(d.reason)}</failure>"
        )
        cases.append(
            f'  <testcase classname="verify.gate" name={quoteattr(d.model.name)} '
            f'file={quoteattr(d.model.source)} time="{d.seconds:.4f}">{body}</testcase>'
        )
    xml = (
        '<?xml version="1.0" encoding="utf-8"?>\n'
        f'<testsuite name="passivity gate" tests="{len(results)}" failures="{failures}" '
        f'errors="0" time="{total:.4f}">\n' + "\n".join(cases) + "\n</testsuite>\n"
    )
    write_atomic(path, xml)
