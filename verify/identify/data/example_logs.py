"""The shipped example logs: simulated Section 4 experiments with known operators.

``verify/data/logs/`` holds, for each example, ``<name>.npz`` (an experiment log in the
format of :mod:`verify.inputs.experiment_log`) and ``<name>.toml`` (the operator model
the simulation used: the ground truth an identification should recover, in the
``verify gate`` model format). Both come from :func:`simulate_experiment` in the paper's
protocol: n = 8 bodies, 12 trials of 15 s at 120 Hz, the reference switching every 15 s,
a seeded reaction time of 0.2-0.5 s per trial ended by a logged start event, operator
noise of standard deviation ``OPERATOR_NOISE`` rad/s on u_h inside the loop and
measurement noise of ``MEASUREMENT_NOISE`` on the logged e and u.

* ``passive_human``: diagonal (1.2 s + 0.8)/(s^2 + 2 s + 1.5), c12 = 1/20, c21 = -1/20
  (passive: a1 b1 >= b0 >= 0 and skew off-diagonals), at k_s = 3.0;
* ``nonpassive_human``: diagonal (0.5 s + 1)/(s^2 + s + 2), c12 = 1/20, c21 = -1/20
  (Re h(jw) = (2 - w^2/2)/|2 - w^2 + jw|^2 < 0 above w = 2 rad/s), at k_s = 2.5.

The logged e, u and d_r are written rounded to ``WRITTEN_DECIMALS`` = 6 decimals
(1e-6 rad and rad/s, as a lab's logger would write them; the measurement noise is
2e-3, so the rounding adds a quantisation noise of 3e-7 standard deviation, far below
it). That is what makes the files the same on every machine: the simulation's last bits
depend on the BLAS and the CPU's vector width (the values differed by up to 1.3e-15
between two machines), and a difference that small changes a value rounded to 1e-6 only
when the value lies within 1.3e-15 of a rounding boundary, which for the 3e5 written
values has a probability of about 1e-3 per regeneration. The times are k / 120 s,
computed exactly the same everywhere, and are written as computed.

Regenerate (byte for byte) with ``python -m verify.identify.data.example_logs [--out DIR]``;
``--check`` compares instead of writing and exits 1 on a difference.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from verify.identify.data.simulated_experiment import (
    MEASUREMENT_NOISE,
    OPERATOR_NOISE,
    simulate_experiment,
)
from verify.inputs.experiment import ExperimentLog, Trial
from verify.inputs.experiment_log import write_log
from verify.passivity.model import LTIModel, from_transfer_function

LOGS = Path(__file__).resolve().parents[2] / "data" / "logs"
#: Decimals of the written e, u and d_r (module docstring).
WRITTEN_DECIMALS = 6


def as_written(log: ExperimentLog, decimals: int = WRITTEN_DECIMALS) -> ExperimentLog:
    """``log`` with e, u and the reference rounded to ``decimals`` decimals (times kept)."""

    def rounded(x: np.ndarray | None) -> np.ndarray | None:
        return None if x is None else np.round(x, decimals) + 0.0  # + 0.0: no -0.0

    trials = tuple(Trial(tr.trial, tr.t, rounded(tr.e), rounded(tr.u), rounded(tr.reference),
                         tr.valid, tr.start, tr.end) for tr in log.trials)
    return ExperimentLog(trials, log.rate, log.source)


@dataclass(frozen=True)
class Example:
    """One shipped experiment: the true diagonal element, couplings, gain and seed."""

    name: str
    title: str
    b: tuple[str, str]  # numerator b1, b0 as decimal text (exact in the TOML file)
    a: tuple[str, str]  # denominator a1, a0 (monic)
    c12: str
    c21: str
    k_s: float
    seed: int
    passive: bool

    def model(self) -> LTIModel:
        from fractions import Fraction

        b = [Fraction(v) for v in self.b]
        a = [Fraction(1), *(Fraction(v) for v in self.a)]
        num = [[b, [Fraction(self.c12)]], [[Fraction(self.c21)], b]]
        den = [[a, [1]], [[1], a]]
        return from_transfer_function(num, den, name=self.title, meta={"k_s": self.k_s})

    def toml(self) -> str:
        b, a = ", ".join(self.b), ", ".join(self.a)
        verdict = ("passive" if self.passive else
                   "NOT passive (Re h(jw) < 0 above w = 2 rad/s)")
        return (
            "# SIMULATION GROUND TRUTH, not identified and not published data: the operator\n"
            f"# model that generated {self.name}.npz beside this file (verify.identify."
            "data.example_logs).\n"
            "# Paper's structure (Section 4): diagonal (b1 s + b0)/(s^2 + a1 s + a0), "
            "constant off-diagonals.\n"
            f"# This model is {verdict}.\n"
            f'name = "{self.title}"\n'
            f'description = "ground truth of the simulated experiment log {self.name}.npz '
            f'(n = 8, 12 trials x 15 s at 120 Hz, seed {self.seed})"\n'
            f"k_s = {self.k_s!r}\n"
            "\n"
            "[transfer_function]      # element (i, j): descending powers of s\n"
            f"num = [[[{b}], [{self.c12}]], [[{self.c21}], [{b}]]]\n"
            f"den = [[[1.0, {a}], [1.0]], [[1.0], [1.0, {a}]]]\n")


EXAMPLES = (
    Example("passive_human", "simulated passive operator", ("1.2", "0.8"), ("2.0", "1.5"),
            "0.05", "-0.05", 3.0, 1, True),
    Example("nonpassive_human", "simulated non-passive operator", ("0.5", "1.0"),
            ("1.0", "2.0"), "0.05", "-0.05", 2.5, 2, False),
)


def generate(out: Path = LOGS, examples=EXAMPLES) -> list[Path]:
    """Simulate each example and write its log and ground-truth model into ``out``."""
    from verify.artefacts.atomic import write_atomic

    paths = []
    for ex in examples:
        log = simulate_experiment(ex.model(), k_s=ex.k_s, n=8, trials=12, trial_seconds=15.0,
                                  rate=120.0, operator_noise=OPERATOR_NOISE,
                                  measurement_noise=MEASUREMENT_NOISE, seed=ex.seed)
        paths.append(write_log(as_written(log), out / f"{ex.name}.npz"))
        toml = out / f"{ex.name}.toml"
        write_atomic(toml, ex.toml())
        paths.append(toml)
    return paths


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m verify.identify.data.example_logs",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=LOGS, help=f"directory (default {LOGS})")
    parser.add_argument("--check", action="store_true",
                        help="regenerate in a temporary directory and compare with --out")
    args = parser.parse_args(argv)
    if not args.check:
        for path in generate(args.out):
            print(f"wrote {path} ({path.stat().st_size} bytes)")
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        fresh = generate(Path(tmp))
        bad = [p.name for p in fresh if not (args.out / p.name).is_file()
               or (args.out / p.name).read_bytes() != p.read_bytes()]
    for name in bad:
        print(f"differs: {args.out / name}")
    print("example logs reproduced byte for byte" if not bad else f"{len(bad)} file(s) differ")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
