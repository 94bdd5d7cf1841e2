"""`verify identify`: experiment logs -> identified H(s) -> nominal and robust verdicts.

The chain of Section 4 ("Human Modeling") as one command a lab runs in CI:

1. read the logs (:mod:`verify.inputs.experiment_log`), apply the protocol (dead time,
   decimation, split by trial: :mod:`verify.identify.data.protocol`);
2. estimate H(s) in the structure (:func:`verify.identify.estimate.estimation.estimate_model`),
   with fit ratios and residual tests (:mod:`verify.identify.quality.fits`);
3. write the nominal model as a ``verify gate`` model file with an ``[identification]``
   table (:mod:`verify.identify.model.model_writer`); the file's decimals are the exact model;
4. the **nominal verdict**: the gate's exact decision on that file (all frequencies, or
   ``--band``), with its certificate when passive;
5. the **robust verdict** over the 95 % confidence region (:mod:`verify.identify.robust.verdict`)
   on the band (or all frequencies), and the largest band [w1, w_max] on which robust
   passivity is proved, each with a certificate that ``verify certificates check`` re-checks;
6. figures (:mod:`verify.identify.figures`), a JSON summary and a JUnit file.

Everything is validated and rendered in memory before the first file is written, and each
file is written atomically (bad input: one line, exit 2, nothing written). Exit 0 only if
the robust verdict is passive on the requested band (or at all frequencies when no band is
given); 1 otherwise.
"""

from __future__ import annotations

import json
import math
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from verify.errors import VerifyInputError
from verify.identify.estimate.result import Estimate
from verify.identify.estimate.structure import Structure
from verify.identify.model.model_writer import (
    IdentifiedFile,
    canonical,
    identification_table,
    model_text,
    parse_structure,
    read_identified,
    structure_text,
)
from verify.identify.quality.fits import PAPER_BASIS, trial_ranges
from verify.identify.quality.identifiability import Identifiability
from verify.identify.robust import band_certificate as rc
from verify.identify.robust.verdict import BandSearch, RobustResult, largest_band, robust_verdict
from verify.inputs.numbers import parse_number
from verify.passivity.decision import INCONCLUSIVE
from verify.progress import Stages, silent

LEVEL = Fraction(19, 20)
MODEL_FILE = "model.toml"
#: What ``--out`` holds when the data do not identify the operator (no model, no
#: certificate).
REFUSAL_FILE = "CANNOT_IDENTIFY.txt"


@dataclass(frozen=True)
class IdentifySettings:
    """The command line of ``verify identify`` (validated by :func:`validate`)."""

    logs: tuple[Path, ...]
    structure: str = "paper"
    rate: str | None = None
    split: str = "6:6"
    band: str | None = None
    out: Path = Path("build/identified")
    json: Path | None = None
    junit: Path | None = None
    name: str | None = None
    max_boxes: int = 40_000
    progress: bool = False  # stage lines on stderr even when it is not a terminal
    offset: bool | None = None  # estimate a constant offset per output (None: the default)


@dataclass(frozen=True)
class Plan:
    """Validated settings."""

    logs: tuple[Path, ...]
    structure: Structure
    rate: float | str
    split: tuple[int, int]
    band: tuple[Fraction, Fraction] | None
    out: Path
    json: Path | None
    junit: Path | None
    name: str
    max_boxes: int
    offset: bool = True


def parse_split(text: str) -> tuple[int, int]:
    """``A:B`` trials for identification and validation, A >= 1, B >= 1."""
    head, sep, tail = str(text).partition(":")
    if sep and head.strip().isdigit() and tail.strip().isdigit():
        a, b = int(head), int(tail)
        if a >= 1 and b >= 1:
            return a, b
    raise VerifyInputError(f"--split {text!r}: expected A:B with A, B >= 1 trials for "
                           "identification and validation, e.g. --split 6:6")


def _check_split(split: tuple[int, int], count: int) -> None:
    """The split against the log's trial count, with advice this command accepts."""
    a, b = split
    if a + b <= count:
        return
    advice = (f"e.g. --split {count - count // 2}:{count // 2}" if count >= 2 else
              "log at least 2 trials (one to identify, one to validate)")
    raise VerifyInputError(f"--split {a}:{b} needs {a + b} trials but the log has {count}; "
                           f"{advice}")


def _check_lengths(log, rate: float | str | None) -> None:
    """Every trial long enough, decimated, for the model (Section 4); shorter is exit 2."""
    from verify.identify.data.protocol import MIN_FILTER_SAMPLES, MIN_MODEL_SAMPLES, decimation_of

    q, _ = decimation_of(log, rate)
    need = max(MIN_FILTER_SAMPLES, q * (MIN_MODEL_SAMPLES - 1) + 1)
    for tr in log.trials:
        if len(tr.t) < need:
            raise VerifyInputError(
                f"{log.source}: trial {tr.trial} has {len(tr.t)} samples; at least {need} are "
                f"needed ({MIN_MODEL_SAMPLES} after decimation by {q} for the model); drop "
                "the trial or record longer")


def parse_rate(text: str | None) -> float | str:
    """``--rate``: a rate in Hz, "off" (no decimation) or "auto" (the default: decimate
    only noisy logs, :func:`verify.identify.data.protocol.chosen_rate`)."""
    if text is None or str(text).strip() == "auto":
        return "auto"
    if str(text).strip() == "off":
        return "off"
    value = parse_number(text, "--rate", "--rate 20")
    if value <= 0:
        raise VerifyInputError(f"--rate {text!r} must be a positive rate in Hz, auto or off, "
                               "e.g. --rate 20")
    return float(value)


def validate(settings: IdentifySettings) -> Plan:
    """Every flag checked before any work (one-line errors)."""
    from verify.artefacts.outputs import OutputPlan
    from verify.passivity.band import parse_band

    structure = parse_structure(settings.structure)
    band = parse_band(settings.band) if settings.band is not None else None
    if not settings.logs:
        raise VerifyInputError("no log files given; pass one or more .csv or .npz logs")
    outputs = OutputPlan(inputs=settings.logs)  # no log replaced, no device written
    outputs.folder("--out", settings.out, replaced=True)
    outputs.file("--json", settings.json)
    outputs.file("--junit", settings.junit)
    if not _ours(settings.out):
        raise VerifyInputError(f"--out {settings.out}: a non-empty directory that is not an "
                               "output of verify identify (it would be replaced); choose a "
                               "new or empty directory")
    name = settings.name or Path(settings.logs[0]).stem
    from verify.identify.estimate.estimation import OFFSET

    offset = OFFSET if settings.offset is None else bool(settings.offset)
    return Plan(tuple(Path(p) for p in settings.logs), structure, parse_rate(settings.rate),
                parse_split(settings.split), band, settings.out, settings.json,
                settings.junit, name, settings.max_boxes, offset)


# ------------------------------------------------------------------ data -> estimate


@dataclass(frozen=True)
class SecondFit:
    """The fit on the estimator's basis (offsets added, or initial states estimated),
    reported beside the paper's and labelled with its ``basis``
    (:func:`verify.identify.quality.fits.second_basis`)."""

    basis: str
    identification: list[float]
    validation: list[float]

    def to_json(self) -> dict[str, Any]:
        return {"basis": self.basis,
                "identification": [canonical(x) for x in self.identification],
                "validation": [canonical(x) for x in self.validation]}


@dataclass
class Quality:
    """Fit ratios (%) per output on identification and validation data: the paper's
    (Section 4, :func:`verify.identify.quality.fits.paper_fits`: each data set simulated
    on its logged input from rest, no offset), and, when the estimate uses offsets or
    estimated initial states, the fit on that basis as a labelled ``second`` figure;
    residual tests (diagnostics only, on the estimator's basis)."""

    fit_identification: list[float]
    fit_validation: list[float]
    tests: dict[str, Any] = field(default_factory=dict)
    validation_times: list[np.ndarray] = field(default_factory=list)
    validation_measured: list[np.ndarray] = field(default_factory=list)
    validation_predicted: list[np.ndarray] = field(default_factory=list)
    basis: str = PAPER_BASIS
    second: SecondFit | None = None

    @property
    def decision_fit(self) -> list[float]:
        """The validation fit the identifiability gate uses: on the estimator's basis
        (an uncalibrated stick's offset does not make a model unidentifiable)."""
        return self.second.validation if self.second is not None else self.fit_validation

    def text(self) -> str:
        """The fit line(s) the command prints."""
        def both(ident: list[float], val: list[float]) -> str:
            return ("identification " + ", ".join(f"{x:.2f}" for x in ident)
                    + "; validation " + ", ".join(f"{x:.2f}" for x in val))

        out = f"fit (%, {self.basis}): " + both(self.fit_identification, self.fit_validation)
        if self.second is not None:
            out += (f"\n  second fit (%, not the paper's basis; {self.second.basis}): "
                    + both(self.second.identification, self.second.validation))
        return out

    def to_json(self) -> dict[str, Any]:
        return {"identification": [canonical(x) for x in self.fit_identification],
                "validation": [canonical(x) for x in self.fit_validation],
                "basis": self.basis,
                "second": None if self.second is None else self.second.to_json()}

    def table(self) -> dict[str, Any]:
        """The fit entries of the model file's [identification] table."""
        out: dict[str, Any] = {
            "fit_identification": [canonical(x) for x in self.fit_identification],
            "fit_validation": [canonical(x) for x in self.fit_validation],
            "fit_basis": self.basis}
        if self.second is not None:
            out.update({
                "fit_second_identification": [canonical(x)
                                              for x in self.second.identification],
                "fit_second_validation": [canonical(x) for x in self.second.validation],
                "fit_second_basis": self.second.basis})
        return out


@dataclass
class Identified:
    """What the data gave: the estimate (None when the estimator found no interior
    minimum), its quality, the identifiability gate, the protocol's facts."""

    estimate: Estimate | None
    quality: Quality | None
    rate: float
    trials: tuple[list[int], list[int]]
    notes: tuple[str, ...] = ()
    gate: Identifiability | None = None
    joins: tuple[str, ...] = ()
    passivity: Any = None  # verify.identify.robust.passive_fit.PassivityTest, or why none
    model_class: Any = None  # verify.identify.quality.model_class.ClassTest, or None

    @property
    def identifiable(self) -> bool:
        return self.gate is None or self.gate.identifiable


def trial_joins(trials: Sequence[Any]) -> tuple[str, ...]:
    """How consecutive trials were joined by the fit and the estimator (per-trial clocks,
    dead-time gaps and pauses, :func:`verify.identify.estimate.trial_data.dead_time_gaps`),
    one line per kind of join, and a warning for each trial that begins mid-response
    (:func:`verify.identify.estimate.trial_data.fresh_starts`)."""
    from verify.identify.estimate.trial_data import (
        MAX_CARRY_GAP,
        START_WINDOW,
        dead_time_gaps,
        fresh_starts,
        mid_response,
        rest_level,
    )

    gaps = dead_time_gaps(trials)
    fresh = fresh_starts(trials)
    level = rest_level(trials)
    carried = [g for g in gaps[1:] if g is not None]
    paused, rest = [], []
    for prev, tr, g in zip(trials, trials[1:], gaps[1:], strict=False):
        if g is not None:
            continue
        pause = float(tr.t[0] - prev.t[-1])
        after_pause = getattr(tr, "resumed", False) or pause > MAX_CARRY_GAP
        (paused if tr.trial != prev.trial and after_pause else rest).append(tr.trial)
    out = [f"trial {trials[0].trial} starts from rest"]
    if carried:
        out.append(f"{len(carried)} trial(s) continue from the state the previous one left, "
                   f"coasted with zero input over a gap of {min(carried):.3g}-"
                   f"{max(carried):.3g} s")
    if paused:
        out.append(f"trial(s) {', '.join(str(t) for t in paused)} follow a pause in the "
                   "log: what the operator did in it is not logged, so they start from "
                   "rest, as after a reset, not from a state coasted over the pause")
    if rest:
        out.append(f"trial(s) {', '.join(str(t) for t in rest)} start independently from "
                   "rest (same trial id as the previous segment, or the clock does not "
                   "move forward)")
    late = [tr for tr, is_fresh in zip(trials, fresh, strict=True) if is_fresh]
    if late:  # one line for all of them, however many
        shares = [100 * mid_response(tr, level) for tr in late]
        span = (f"{min(shares):.0f} %" if round(min(shares)) == round(max(shares))
                else f"{min(shares):.0f}–{max(shares):.0f} %")
        ids = sorted({tr.trial for tr in late})
        noun, verb, its = (("trial", "begins", "its initial state is") if len(ids) == 1
                           else ("trials", "begin", "their initial states are"))
        out.append(f"warning: {noun} {trial_ranges(ids)} {verb} mid-response (u at {span} "
                   f"of its largest value over its first {START_WINDOW:g} s, from the rest "
                   f"level): {its} estimated for the estimator and the second fit figure; "
                   "the paper's fit starts them from rest (logging started during a "
                   "response: in closed loop that estimate is biased; log from before the "
                   "response where possible)")
    return tuple(out)


def identify_logs(plan: Plan, stage: Callable[[str], None] = silent) -> Identified:
    """Logs -> prepared trials -> estimate, honest fits and the identifiability gate
    (steps 1 and 2); ``stage`` is told each step as it starts (progress lines)."""
    from verify.identify.data.protocol import MIN_FILTER_SAMPLES, prepare
    from verify.identify.estimate.estimation import estimate_model
    from verify.identify.estimate.result import CannotIdentifyError
    from verify.identify.quality import identifiability
    from verify.identify.quality.fits import (
        assess,
        fit_ratios,
        honest_fits,
        paper_fits,
        second_basis,
    )
    from verify.identify.quality.model_class import model_class_test
    from verify.inputs.experiment_log import read_logs

    stage(f"reading {len(plan.logs)} log(s) and preparing the trials")
    log = read_logs(plan.logs, min_samples=MIN_FILTER_SAMPLES)  # shorter: one line, exit 2
    _check_split(plan.split, len(log.trials))
    _check_lengths(log, plan.rate)
    prepared = prepare(log, rate=plan.rate, split=plan.split)
    ids = sorted({t.trial for t in prepared.identification})
    vals = sorted({t.trial for t in prepared.validation})
    joined = [*prepared.identification, *prepared.validation]
    joins = trial_joins(joined)
    more, figures = identifiability.data_reasons(joined)
    if more:  # not the loop's signals, or a diverging loop: nothing to estimate
        gate = identifiability.Identifiability(False, tuple(more), figures)
        return Identified(None, None, prepared.rate, (ids, vals), prepared.notes, gate, joins)
    try:
        st = plan.structure
        shape = {"paper": "the paper's structure", "order": f"order {st.states}"}.get(
            st.kind, f"structure {st.poles}:{st.zeros}")
        stage(f"estimating the model ({shape}) from {len(ids)} trial(s)")
        estimate = estimate_model(prepared.identification, plan.structure,
                                  offset=plan.offset)
    except CannotIdentifyError as exc:
        gate = identifiability.Identifiability(False, (str(exc),), figures)
        return Identified(None, None, prepared.rate, (ids, vals), prepared.notes, gate, joins)
    stage(f"simulating the fits on {len(ids)} + {len(vals)} trial(s)")
    p_id, p_val = paper_fits(estimate, prepared.identification, prepared.validation)
    y_id, y_val = honest_fits(estimate, prepared.identification, prepared.validation)
    on_val = assess(estimate, prepared.validation, yhat=y_val)  # residuals: the estimator's
    basis = second_basis(estimate, prepared.identification, prepared.validation)
    second = None if basis is None else SecondFit(
        basis, fit_ratios(prepared.identification, y_id),
        [float(x) for x in on_val.fit])
    quality = Quality(
        fit_ratios(prepared.identification, p_id), fit_ratios(prepared.validation, p_val),
        residual_tests(on_val), [np.asarray(t.t) for t in prepared.validation],
        [np.asarray(t.u) for t in prepared.validation], list(p_val), second=second)
    stage("checking identifiability")
    gate = identifiability.check(
        estimate, quality.decision_fit, joined, 1.0 / prepared.rate,
        basis="" if second is None else "the second figure's basis: the estimator's")
    if gate.identifiable:
        stage("testing the model class against a larger one")
    model_class = (model_class_test(estimate, prepared.identification) if gate.identifiable
                   else None)
    if gate.identifiable:
        stage("fitting the best passive model of the class (passivity test)")
    passivity = (_passivity(estimate, prepared.identification, model_class, stage)
                 if gate.identifiable else None)
    return Identified(estimate, quality, prepared.rate, (ids, vals), prepared.notes, gate,
                      joins, passivity, model_class)


def _passivity(estimate: Estimate, trials, model_class: Any,
               stage: Callable[[str], None] = silent) -> Any:
    """Can the data reject passivity (:mod:`verify.identify.robust.passive_fit`), asked
    only where the fitted class holds: when the data reject the class, the best passive
    model *of the class* against the best model of the class says nothing about the
    operator (a passive third-order operator gave p = 1.7e-11 there), so the answer is
    the reason the question cannot be answered within the class."""
    from verify.identify.robust.passive_fit import test_or_reason

    if model_class is not None and model_class.rejected:
        return (f"not answered: the data reject the fitted class against "
                f"{model_class.larger_text()}, so whether a passive model of the class "
                "explains the data says nothing about the operator (fit the larger class, "
                f"--structure {model_class.larger_text()}, to ask it there)")
    return test_or_reason(estimate, trials, stage)


def _offset_table(est: Estimate) -> dict[str, Any]:
    """The estimated offsets of the logged outputs for the model file's [identification]
    table (nuisance parameters: not part of the model's H(s)), or nothing."""
    if not est.offsets:
        return {"offsets": "not estimated"}
    return {"offsets": _offset_values(est),
            "offset_standard_errors": [canonical(x) for x in est.offset_errors]}


def _offset_values(est: Estimate) -> list[float]:
    """The offsets to the digits their standard errors justify, as the coefficients are
    written (float noise far below them never changes a written digit)."""
    from verify.identify.model.model_writer import coefficient_text

    return [float(coefficient_text(x, e)) for x, e in
            zip(est.offsets, est.offset_errors, strict=True)]


def residual_tests(q: Any) -> dict[str, Any]:
    """The residual tests of :func:`verify.identify.quality.fits.assess` on the validation
    data, as numbers for the model file's [identification] table (diagnostics: they
    never stop the command; a test that could not be computed is listed with why)."""
    white = sorted(q.whiteness, key=lambda t: t.output)
    cross = sorted(q.cross_correlation, key=lambda t: (t.output, t.input))
    out: dict[str, Any] = {"residual_tests_data": "validation"}
    if white:
        out.update({"whiteness_statistic": [canonical(t.statistic) for t in white],
                    "whiteness_threshold": canonical(white[0].threshold),
                    "whiteness_lags": int(white[0].lags)})
    if cross:
        out.update({"cross_correlation_statistic": [
            [canonical(t.statistic) for t in cross if t.output == i] for i in (1, 2)],
            "cross_correlation_threshold": canonical(cross[0].threshold)})
    if white or cross:
        out["residual_tests_level"] = float((white or cross)[0].level)
    if q.not_computed:
        out["residual_tests_not_computed"] = list(q.not_computed)
    out["residual_tests_passed"] = bool(q.residuals_pass)
    return out


# ------------------------------------------------------------------ estimate -> verdicts


@dataclass
class Outcome:
    """Everything the command prints and writes, rendered in memory."""

    plan: Plan
    identified: Identified
    model_path: Path
    ident: IdentifiedFile
    nominal: Any  # Decision or BandDecision
    nominal_certificate: tuple[str, str] | None  # (file name, text)
    robust: RobustResult
    band_search: BandSearch
    files: dict[Path, bytes | str]
    high_frequency_note: str
    model_class_note: str = ""

    @property
    def passed(self) -> bool:
        return self.robust.passed


def _sha256(path: Path) -> str:
    """The log's SHA-256 (provenance in the model file, independent of where it lies)."""
    import hashlib

    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def _high_frequency_note(structure: Structure, center: Sequence[Any]) -> str:
    c = Fraction(center[-2]) + Fraction(center[-1])
    if structure.zeros >= structure.poles:
        return ""
    if c == 0:
        return ("c12 + c21 = 0 exactly: the off-diagonal elements do not prevent passivity "
                "at high frequency")
    return (f"c12 + c21 = {float(c):.6g} is not 0 while Re h_i(jω) -> 0 as ω -> ∞ (strictly "
            "proper diagonal elements), so det(H(jω) + H(jω)ᴴ) -> -(c12 + c21)² < 0: this "
            "model is not passive at all frequencies. For the paper's class an identified "
            "c12 + c21 is never exactly 0, so this holds for almost every identified model; "
            "what can hold is passivity on a band [0, w_max]")


def _nominal(model, band, certs_dir: Path):
    from verify.passivity.gate import run_band_gate, run_gate

    if band is None:
        (result,) = run_gate([model], Fraction(0), certs_dir)
    else:
        (result,) = run_band_gate([model], band, Fraction(0), certs_dir)
    return result


def decide_identified(plan: Plan, identified: Identified, *, band_steps: int = 7,
                      stage: Callable[[str], None] = silent) -> Outcome:
    """Steps 3 to 6, in a temporary directory; returns the files to write.

    ``band_steps`` bounds the bisection for the largest proved band. Only for data the
    identifiability gate passed (:class:`CannotIdentifyError` otherwise)."""
    from verify.identify.estimate.result import CannotIdentifyError
    from verify.identify.robust.model_class_check import check_answers

    if not identified.identifiable or identified.estimate is None:
        raise CannotIdentifyError("cannot identify: " + "; ".join(identified.gate.reasons))
    est = identified.estimate
    q = identified.quality
    extra = {
        "method": est.method,
        "covariance_kind": getattr(est, "covariance_kind", "asymptotic"),
        "covariance_inflation": canonical(est.inflation, 6),
        "rate": float(identified.rate),
        "split": f"{plan.split[0]}:{plan.split[1]}",
        "trials_identification": identified.trials[0],
        "trials_validation": identified.trials[1],
        "samples": int(est.samples),
        "noise_std": [canonical(x) for x in est.noise_std],
        **_offset_table(est),
        **q.table(),
        "trial_joins": list(identified.joins),
        **{k: v for k, v in q.tests.items()},
        "logs": [p.name for p in plan.logs],
        "logs_sha256": [_sha256(p) for p in plan.logs],
    }
    table = identification_table(est.structure, est.theta, est.covariance, LEVEL, extra)
    text, _ = model_text(plan.name, est.structure, est.theta, table,
                         description="identified from experiment logs by verify identify")
    model_path = plan.out / MODEL_FILE
    files: dict[Path, bytes | str] = {model_path: text}
    with tempfile.TemporaryDirectory(prefix="verify-identify-") as tmp:
        tmp_model = Path(tmp) / MODEL_FILE
        tmp_model.write_text(text)
        ident = read_identified(tmp_model)
        model = replace(ident.model, source=str(model_path))
        ident = replace(ident, model=model)
        try:
            region, no_region = ident.region(), ""
        except VerifyInputError as exc:  # e.g. a singular covariance: no ellipsoid
            region, no_region = None, str(exc).removeprefix(f"{tmp_model}: ")
        certs = Path(tmp) / "certificates"
        stage("deciding the nominal model's passivity exactly")
        nominal = _nominal(model, plan.band, certs)
        nominal_cert = None
        if nominal.certificate_path is not None:
            nominal_cert = (nominal.certificate_path.name, nominal.certificate_path.read_text())
            files[plan.out / nominal_cert[0]] = nominal_cert[1]
    source = str(model_path)
    w1 = plan.band[0] if plan.band is not None else Fraction(0)
    if region is None:
        robust = RobustResult(INCONCLUSIVE, plan.band, "no confidence region to decide "
                              f"over: {no_region}")
        search = BandSearch(w1, None, None)
    else:
        stage("deciding passivity over the whole confidence region (interval boxes)")
        robust = robust_verdict(region, est.structure, plan.band, name=plan.name,
                                source=source, nominal=nominal.decision,
                                max_boxes=plan.max_boxes)
        nyquist = math.pi * float(identified.rate)
        stage(f"searching the largest band proved passive ({band_steps} bisection steps)")
        search = largest_band(region, est.structure, w1, nyquist, name=plan.name,
                              source=source, steps=band_steps,
                              max_boxes=max(1000, plan.max_boxes // 4))
    robust, search, class_note = check_answers(identified.model_class, robust, search)
    for cert in (robust.certificate, search.certificate):
        if cert is not None:
            band = None if cert["band"] is None else tuple(Fraction(x) for x in cert["band"])
            files[plan.out / rc.file_name(cert["name"], band, cert["fingerprint"])] = \
                rc.dumps(cert)
    files.update(robust.files(plan.out))
    files.update(_passive_files(plan, identified))
    stage("drawing the figures")
    files.update(_figures(plan, identified, region, search))
    return Outcome(plan, identified, model_path, ident, nominal, nominal_cert, robust,
                   search, files, _high_frequency_note(est.structure, ident.center),
                   class_note)


def _figures(plan: Plan, identified: Identified, region, search: BandSearch
             ) -> dict[Path, bytes]:
    from verify.identify import figures as fg

    structure = identified.estimate.structure
    out: dict[Path, bytes] = {}
    q = identified.quality
    d = plan.out / "figures"
    if q.validation_times:
        out[d / "validation.png"] = fg.validation_figure(
            q.validation_times, q.validation_measured, q.validation_predicted,
            q.fit_validation)
    est = identified.estimate
    center = np.asarray(est.theta, dtype=float) if region is None else region.float_center()
    top = max(10.0, math.pi * float(identified.rate))
    omega = np.geomspace(1e-2, top, 400)
    out[d / "bode.png"] = fg.bode_figure(
        structure, center, None if region is None else region.float_covariance(),
        0.0 if region is None else float(region.chi2), omega, LEVEL)
    proved = None if search.w_max is None else (float(search.w1), float(search.w_max))
    requested = None if plan.band is None else (float(plan.band[0]), float(plan.band[1]))
    out[d / "nu.png"] = fg.nu_figure(structure, center, omega, proved, requested)
    return out


# ------------------------------------------------------------------ reporting


def summary_json(o: Outcome) -> dict[str, Any]:
    """The JSON summary (``--json``)."""
    est = o.identified.estimate
    q = o.identified.quality
    nominal = o.nominal.decision.to_json()
    return {
        "logs": [str(p) for p in o.plan.logs],
        "structure": structure_text(est.structure),
        "rate": o.identified.rate,
        "split": list(o.plan.split),
        "trials": {"identification": o.identified.trials[0],
                   "validation": o.identified.trials[1]},
        "estimate": {"method": est.method, "names": list(est.names),
                     "theta": [float(x) for x in o.ident.center],
                     "written": [str(x) for x in o.ident.center],
                     "standard_errors": [canonical(math.sqrt(max(v, 0.0)))
                                         for v in np.diag(est.covariance)],
                     "offsets": _offset_values(est),
                     "offset_standard_errors": [canonical(x) for x in est.offset_errors]},
        "fit": q.to_json(),
        "trial_joins": list(o.identified.joins),
        "protocol": list(o.identified.notes),
        "identifiability": o.identified.gate.to_json() if o.identified.gate else None,
        "residual_tests": q.tests,
        "model": str(o.model_path),
        "nominal": {**nominal, "passed": o.nominal.passed,
                    "certificate": None if o.nominal_certificate is None else
                    str(o.plan.out / o.nominal_certificate[0]),
                    "kernel": _kernel(str(o.nominal.decision.verdict)), "coq_theorem": None},
        "robust": {**o.robust.to_json(), "level": str(LEVEL),
                   "certificate": _cert_path(o, o.robust.certificate),
                   **_robust_answer(o), "kernel": _kernel(str(o.robust.verdict)),
                   "coq_theorem": None},
        "largest_band": {**o.band_search.to_json(),
                         "certificate": _cert_path(o, o.band_search.certificate),
                         "kernel": _kernel("passive" if o.band_search.certificate
                                           else "inconclusive"), "coq_theorem": None},
        "high_frequency": o.high_frequency_note,
        "passivity_test": _passivity_json(o),
        "model_class": None if o.identified.model_class is None else {
            **o.identified.model_class.to_json(), "answers": o.model_class_note},
        "passed": o.passed,
    }


def _kernel(verdict: str) -> str:
    """The kernel status of a verdict of this command (see ``verify gate --coq``): every
    verdict here is decided by the exact Python checkers; its certificate files become
    Coq units with ``verify coq FILES --check``."""
    if verdict in ("passive", "not passive"):
        return "exact-python"
    return f"not-exported: no verdict to prove ({verdict})"


def _passive_files(plan: Plan, identified: Identified) -> dict[Path, bytes | str]:
    """The best passive model's file, when the passivity test ran."""
    from verify.identify.robust.passive_fit import PASSIVE_MODEL_FILE, passive_model_text

    test = identified.passivity
    if test is None or isinstance(test, str) or not test.informative:
        return {}
    try:
        errors = np.sqrt(np.clip(np.diag(identified.estimate.covariance), 0.0, None))
        text = passive_model_text(f"{plan.name} (best passive fit)", test,
                                  errors=[float(e) for e in errors])
    except VerifyInputError:
        return {}
    return {plan.out / PASSIVE_MODEL_FILE: text}


def _passivity_json(o: Outcome) -> Any:
    from verify.identify.robust.passive_fit import PASSIVE_MODEL_FILE

    test = o.identified.passivity
    if test is None or isinstance(test, str):
        return {"ran": False, "reason": test}
    path = o.plan.out / PASSIVE_MODEL_FILE
    return {"ran": True, **test.to_json(),
            "passive_model": str(path) if path in o.files else None}


def _robust_answer(o: Outcome) -> dict[str, Any]:
    """The robust answer's JSON fields: which of the three, and its certificate."""
    name = o.robust.refutation_name()
    return {"answer": o.robust.headline(),
            "refutation_certificate": None if name is None else str(o.plan.out / name),
            "largest_proved_band": None if o.band_search.w_max is None else
            [str(o.band_search.w1), str(o.band_search.w_max)]}


def _cert_path(o: Outcome, cert: dict | None) -> str | None:
    if cert is None:
        return None
    band = None if cert["band"] is None else tuple(Fraction(x) for x in cert["band"])
    return str(o.plan.out / rc.file_name(cert["name"], band, cert["fingerprint"]))


def junit(o: Outcome) -> str:
    """JUnit XML: the nominal and the robust verdict, one test case each."""
    from verify.passivity.gate import JunitCase, junit_text

    where = o.robust.where()
    d = o.nominal.decision
    return junit_text([
        JunitCase("verify.identify", f"nominal: {o.plan.name}", str(o.model_path), d.seconds,
                  o.nominal.passed, str(d.verdict), d.reason,
                  (("kernel", _kernel(str(d.verdict))),)),
        JunitCase("verify.identify", f"robust ({float(LEVEL):.0%} region) {where}: "
                  f"{o.plan.name}", str(o.model_path), o.robust.seconds, o.robust.passed,
                  str(o.robust.verdict), f"{o.robust.headline()}. {o.robust.reason}",
                  (("kernel", _kernel(str(o.robust.verdict))),)),
    ], suite="identification")


def lines(o: Outcome) -> list[str]:
    """What the command prints."""
    est = o.identified.estimate
    q = o.identified.quality
    out = [f"identified {o.plan.name}: structure {structure_text(est.structure)}, "
           f"{est.method}, {o.identified.rate:g} Hz, trials {o.identified.trials[0]} "
           f"(identification) / {o.identified.trials[1]} (validation)"]
    out.append("  " + q.text())
    out.append("  trials joined: " + "; ".join(o.identified.joins))
    out.append("  protocol: " + "; ".join(o.identified.notes))
    se = np.sqrt(np.clip(np.diag(est.covariance), 0, None))
    out.append("  parameters: " + ", ".join(
        f"{n} = {float(c):.10g} ± {s:.2g}" for n, c, s in zip(est.names, o.ident.center, se,
                                                            strict=True)))
    if est.offsets:
        out.append("  offsets of the logged u (estimated with the model, not part of "
                   "H(s)): " + ", ".join(f"u{i + 1} {x:+.3g} ± {s:.2g}" for i, (x, s) in
                                         enumerate(zip(est.offsets, est.offset_errors,
                                                       strict=True))))
    out.append(f"  model file: {o.model_path}")
    d = o.nominal.decision
    out.append(f"  nominal ({'all frequencies' if o.plan.band is None else o.robust.where()})"
               f": {d.verdict}: {d.reason}")
    out.append(f"  robust, every model of the {float(LEVEL):.0%} region "
               f"{o.robust.where()}: {o.robust.verdict}: {o.robust.reason}")
    out += _robust_lines(o)
    out += _model_class_lines(o)
    out += _passivity_lines(o)
    if o.high_frequency_note:
        out.append(f"  note: {o.high_frequency_note}")
    b = o.band_search
    if b.w_max is not None:
        out.append(f"  robust passivity proved on [{b.w1}, {b.w_max}] rad/s "
                   f"(≈ [{float(b.w1):.4g}, {float(b.w_max):.4g}]; the largest band the "
                   "prover reached, bisection on w_max)")
    else:
        out.append("  robust passivity proved on no band [w1, w_max] tried")
    return out


def _model_class_lines(o: Outcome) -> list[str]:
    """The test of the fitted class against a larger one, and what it did to the answers."""
    test = o.identified.model_class
    if test is None:
        return []
    out = [f"  model class {structure_text(test.structure)}: {test.sentence()}"]
    if o.model_class_note:
        out.append(f"  {o.model_class_note}")
    return out


def _passivity_lines(o: Outcome) -> list[str]:
    from verify.identify.robust.passive_fit import PASSIVE_MODEL_FILE, summary_lines

    path = o.plan.out / PASSIVE_MODEL_FILE
    return summary_lines(o.identified.passivity, path if path in o.files else None)


def _robust_lines(o: Outcome) -> list[str]:
    """The robust answer in one line, with its certificate or the largest proved band."""
    name = o.robust.refutation_name()
    out = [f"  robust answer: {o.robust.headline()}"]
    if name is not None:
        out.append(f"  refutation certificate: {o.plan.out / name}")
    if o.robust.verdict == INCONCLUSIVE and o.band_search.w_max is not None:
        out.append(f"  the whole region is proved passive on [{o.band_search.w1}, "
                   f"{o.band_search.w_max}] rad/s, the largest band proved")
    return out


def render(plan: Plan) -> Outcome:
    """All work, no file written."""
    return decide_identified(plan, identify_logs(plan))


def _ours(directory: Path) -> bool:
    """True if ``directory`` holds a previous output of this command (or nothing)."""
    if not directory.exists():
        return True
    entries = {p.name for p in directory.iterdir()}
    if not entries or entries == {REFUSAL_FILE}:
        return True
    if MODEL_FILE not in entries:
        return False
    try:
        read_identified(directory / MODEL_FILE)
    except VerifyInputError:
        return False
    return True


def write(o: Outcome) -> None:
    """Every file, after everything is rendered: the output directory is built beside
    ``--out`` and renamed into place (a previous output there is replaced whole, so no
    stale certificate survives); the JSON and JUnit files are written atomically."""
    others: dict[Path, bytes | str] = {}
    if o.plan.json is not None:
        others[o.plan.json] = json.dumps(summary_json(o), indent=2) + "\n"
    if o.plan.junit is not None:
        others[o.plan.junit] = junit(o)
    _write_bundle(o.plan.out, dict(o.files), others)


def _write_bundle(out: Path, bundle: dict[Path, bytes | str],
                  others: dict[Path, bytes | str]) -> None:
    """``bundle`` (files under ``out``) built beside ``out`` and renamed into place, then
    ``others`` (JSON, JUnit) atomically (see :func:`write`)."""
    import os
    import shutil

    from verify.artefacts.atomic import (
        make_parents,
        os_errors_as_output_errors,
        remove_empty,
        write_all_atomic,
    )

    created = make_parents(out.parent)
    staging: Path | None = None
    try:
        with os_errors_as_output_errors(out):
            staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.", dir=out.parent))
            write_all_atomic({staging / p.relative_to(out): data
                              for p, data in bundle.items()})
            inside = {p: d for p, d in others.items() if _within(p, out)}
            write_all_atomic({staging / p.relative_to(out): d for p, d in inside.items()})
            os.chmod(staging, 0o777 & ~_umask())
            if out.exists():
                old = Path(tempfile.mkdtemp(prefix=f".{out.name}.old.", dir=out.parent))
                os.replace(out, old / "previous")
                try:
                    os.replace(staging, out)
                except BaseException:  # the previous output goes back in place
                    os.replace(old / "previous", out)
                    os.rmdir(old)
                    raise
                shutil.rmtree(old, ignore_errors=True)
            else:
                os.replace(staging, out)
    except BaseException:
        if staging is not None:
            shutil.rmtree(staging, ignore_errors=True)
        remove_empty(created)
        raise
    write_all_atomic({p: d for p, d in others.items() if not _within(p, out)})


def _within(path: Path, directory: Path) -> bool:
    try:
        path.resolve().relative_to(directory.resolve())
    except ValueError:
        return False
    return True


def _umask() -> int:
    import os

    mask = os.umask(0)
    os.umask(mask)
    return mask


# ------------------------------------------------------------------ cannot identify


def refusal_lines(plan: Plan, identified: Identified) -> list[str]:
    """What the command prints when the identifiability gate fails."""
    out = [f"cannot identify {plan.name}: no model is certified and no certificate is "
           "written, because:"]
    out += [f"  - {r}" for r in identified.gate.reasons]
    q, est = identified.quality, identified.estimate
    if q is not None:
        out.append("  " + q.text())
    if est is not None:
        out.append("  estimate (not certified): " + ", ".join(
            f"{n} = {float(x):.4g}" for n, x in zip(est.names, est.theta, strict=True)))
    out.append("  trials joined: " + "; ".join(identified.joins))
    out.append("  protocol: " + "; ".join(identified.notes))
    return out


def refusal_json(plan: Plan, identified: Identified) -> dict[str, Any]:
    q, est = identified.quality, identified.estimate
    return {
        "logs": [str(p) for p in plan.logs],
        "structure": structure_text(plan.structure),
        "rate": identified.rate,
        "split": list(plan.split),
        "trials": {"identification": identified.trials[0],
                   "validation": identified.trials[1]},
        "verdict": "cannot identify",
        "identifiability": identified.gate.to_json(),
        "estimate": None if est is None else {
            "method": est.method, "names": list(est.names),
            "theta": [canonical(x, 6) for x in est.theta]},
        "fit": None if q is None else q.to_json(),
        "residual_tests": None if q is None else q.tests,
        "trial_joins": list(identified.joins),
        "protocol": list(identified.notes),
        "model": None,
        "passed": False,
    }


def write_refusal(plan: Plan, identified: Identified) -> None:
    """``--out`` replaced by a directory holding only :data:`REFUSAL_FILE` (no model
    file, no certificate), then the JSON and JUnit files."""
    from verify.passivity.gate import JunitCase, junit_text

    text = "\n".join(refusal_lines(plan, identified)) + "\n"
    others: dict[Path, bytes | str] = {}
    if plan.json is not None:
        others[plan.json] = json.dumps(refusal_json(plan, identified), indent=2) + "\n"
    if plan.junit is not None:
        others[plan.junit] = junit_text([JunitCase(
            "verify.identify", f"identifiability: {plan.name}", str(plan.out), 0.0, False,
            "cannot identify", "; ".join(identified.gate.reasons))], suite="identification")
    _write_bundle(plan.out, {plan.out / REFUSAL_FILE: text}, others)


def run_identify(settings: IdentifySettings) -> int:
    """The command: 0 if the robust verdict is passive, 1 if not, VerifyInputError on bad
    input (exit 2, nothing written)."""
    start = time.perf_counter()
    plan = validate(settings)
    stage = Stages.for_command("verify identify", forced=settings.progress)
    identified = identify_logs(plan, stage)
    if not identified.identifiable:
        write_refusal(plan, identified)
        for line in refusal_lines(plan, identified):
            print(line, flush=True)
        print(f"FAIL: cannot identify ({time.perf_counter() - start:.1f} s); nothing "
              f"certified, reasons in {plan.out / REFUSAL_FILE}")
        return 1
    outcome = decide_identified(plan, identified, stage=stage)
    stage(f"writing the files to {plan.out}")
    write(outcome)
    for line in lines(outcome):
        print(line, flush=True)
    print(f"{'PASS' if outcome.passed else 'FAIL'}: robust verdict {outcome.robust.verdict} "
          f"{outcome.robust.where()} ({time.perf_counter() - start:.1f} s); files in "
          f"{plan.out}")
    return 0 if outcome.passed else 1


__all__ = ["IdentifySettings", "Outcome", "Plan", "Quality", "decide_identified",
           "identify_logs", "junit", "parse_split", "render", "run_identify", "summary_json",
           "validate"]
