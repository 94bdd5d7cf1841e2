"""The robust verdict's prover: time, leaves and the largest proved band vs region size.

A model of the paper's class (the shipped k_s = 3.0 reconstruction's diagonal, c12 + c21
= 0.02) with a correlated covariance scaled by a relative standard deviation; for each
scale: the time of the float branch and bound plus the exact check on a fixed band, the
number of leaves and the certificate's size, the exact re-check alone, and the largest band
[0, w_max] found by bisection (with the nominal crossing for comparison: the robust band
is below it, the gap being the region's width plus the box enclosure's conservatism).

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

from verify.identify import robust_certificate as rc
from verify.identify.region import make_region
from verify.identify.robust import largest_band, nominal_crossing, prove
from verify.identify.structure import Structure


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
            assert rc.check_leaves(cert, rc.shape_of("paper"), region, band) is None
        t_check = time.perf_counter() - start
        start = time.perf_counter()
        found = largest_band(region, structure, Fraction(0), 100.0, name="bench", source="")
        t_search = time.perf_counter() - start
        cross = nominal_crossing(region, structure, 0.0, 100.0)
        w = "-" if found.w_max is None else f"{float(found.w_max):.3g}"
        print(f"{scale:8.3g} {t_prove:13.2f} {leaves:7d} {size:8d} {t_check:8.2f} {w:>8} "
              f"{t_search:9.2f} {cross:10.3g}" + ("" if cert else f"  ({reason})"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
