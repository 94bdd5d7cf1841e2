"""The robust verdict's prover: time, leaves and the largest proved band vs region size.

A model of the paper's class (the shipped k_s = 3.0 reconstruction's diagonal, c12 + c21
= 0.02) with a correlated covariance scaled by a relative standard deviation; for each
scale: the time of the float branch and bound plus the exact check on a fixed band, the
number of leaves and the certificate's size, the exact re-check alone, and the largest band
[0, w_max] found by bisection (with the nominal crossing for comparison: the robust band
is below it, the gap being the region's width plus the box enclosure's conservatism).

A second table does the same for the region-wide refutation (*not passive* for every
model of the region): a model whose element 1 has a1 b1 < b0 (Re h_1(jw) < 0 above
w = sqrt(3) rad/s) on [0, 3] rad/s, per scale the time to find and exactly check the
refutation certificate, its leaves, the exact re-check alone, and the ratio to the
baseline measured in the same process: the single-model refutation (one model of the
region with the gate's exact witness), which is all the verdict had before.

    PYTHONPATH=. python benchmarks/bench_identify_robust.py [--scales 0.005 0.02 0.05]
"""

from __future__ import annotations

import argparse
import sys
import time
from fractions import Fraction
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from identify_models import PAPER_THETA, correlated_covariance

from verify.identify.estimate.structure import Structure
from verify.identify.model.region import make_region
from verify.identify.robust import band_certificate as rc
from verify.identify.robust import band_check, refutation_check
from verify.identify.robust.refutation_search import refute_region
from verify.identify.robust.verdict import largest_band, nominal_crossing, prove, refute


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scales", type=float, nargs="+", default=[0.005, 0.02, 0.05])
    parser.add_argument("--band", type=float, default=4.0, help="fixed band end (rad/s)")
    args = parser.parse_args(argv)
    structure = Structure.paper()
    theta = [Fraction(str(x)) for x in PAPER_THETA]
    band = (Fraction(0), Fraction(str(args.band)))
    print(f"{'rel. std':>8} {'prove [0,W] s':>13} {'leaves':>7} {'bytes':>8} "
          f"{'check s':>8} {'w_max':>8} {'search s':>9} {'nominal x':>10}")
    for scale in args.scales:
        cov = correlated_covariance(PAPER_THETA, relative=scale, coupling=scale / 4)
        region = make_region(theta, cov, Fraction(19, 20))
        start = time.perf_counter()
        cert, reason = prove(region, structure, band, name="bench", source="")
        t_prove = time.perf_counter() - start
        leaves = cert["leaves"] if cert else 0
        size = len(rc.dumps(cert)) if cert else 0
        start = time.perf_counter()
        if cert:
            assert band_check.check_leaves(cert, rc.shape_of("paper"), region, band) is None
        t_check = time.perf_counter() - start
        start = time.perf_counter()
        found = largest_band(region, structure, Fraction(0), 100.0, name="bench", source="")
        t_search = time.perf_counter() - start
        cross = nominal_crossing(region, structure, 0.0, 100.0)
        w = "-" if found.w_max is None else f"{float(found.w_max):.3g}"
        print(f"{scale:8.3g} {t_prove:13.2f} {leaves:7d} {size:8d} {t_check:8.2f} {w:>8} "
              f"{t_search:9.2f} {cross:10.3g}" + ("" if cert else f"  ({reason})"))
    refutations(args.scales)
    return 0


#: Element 1 with a1 b1 = 0.4 < b0 = 0.8: not passive above sqrt(3) rad/s.
LOSSY = [0.2, 0.8, 2.0, 1.5, 1.1, 0.9, 2.1, 1.4, 0.06, -0.04]


def refutations(scales: list[float]) -> None:
    """The region-wide refutation against the single-model one (same process)."""
    structure = Structure.paper()
    theta = [Fraction(str(x)) for x in LOSSY]
    band = (Fraction(0), Fraction(3))
    print(f"\n{'rel. std':>8} {'single s':>9} {'region s':>9} {'ratio':>6} {'leaves':>7} "
          f"{'check s':>8}  verdict")
    for scale in scales:
        cov = correlated_covariance(LOSSY, relative=scale, coupling=scale / 4)
        region = make_region(theta, cov, Fraction(19, 20))
        start = time.perf_counter()
        single = refute(region, structure, band)
        t_single = time.perf_counter() - start
        start = time.perf_counter()
        found = refute_region(region, "paper", band, name="bench", source="")
        t_region = time.perf_counter() - start
        cert = found.certificate
        start = time.perf_counter()
        if cert:
            w = Fraction(cert["frequency"])
            v = tuple(Fraction(x) for x in cert["direction"])
            assert refutation_check.check_tree(cert, rc.shape_of("paper"), region, w, v) is None
        t_check = time.perf_counter() - start
        verdict = "not passive (whole region)" if cert else \
            f"no refutation ({found.reason[:60]})"
        print(f"{scale:8.3g} {t_single:9.2f} {t_region:9.2f} "
              f"{t_region / max(t_single, 1e-9):6.1f} {cert['leaves'] if cert else 0:7d} "
              f"{t_check:8.2f}  {verdict}" + ("" if single else " [no single model]"))


if __name__ == "__main__":
    raise SystemExit(main())
