"""The public passivity API (:mod:`verify.passivity.api`): every model form, and one
``VerifyInputError`` with a one-line message for every bad argument (paper, Section 4)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import verify.passivity as vp
from verify.errors import VerifyInputError
from verify.passivity import GateVerdict

# (0.5 s + 1)/(s^2 + s + 2): nu(w) >= 0 up to w = 2, negative beyond (nu(3) < 0)
NUM, DEN = [0.5, 1], [1, 1, 2]


def forms():
    control = pytest.importorskip("control")
    from scipy import signal

    A = np.array([[0.0, 1.0], [-2.0, -1.0]])
    B = np.array([[0.0], [1.0]])
    C = np.array([[1.0, 0.5]])
    D = np.array([[0.0]])
    return {
        "control tf": control.tf(NUM, DEN),
        "control ss": control.ss(A, B, C, D),
        "scipy tf": signal.TransferFunction(NUM, DEN),
        "scipy ss": signal.StateSpace(A, B, C, D),
        "numpy (num, den)": (np.array(NUM), np.array(DEN)),
        "lists (num, den)": (NUM, DEN),
        "numpy (A, B, C, D)": (A, B, C, D),
    }


def test_every_form_gives_the_same_band_verdicts():
    """The issue's example: decide_band on a python-control object and a float band."""
    for label, H in forms().items():
        assert vp.decide_band(H, (0, 1.5)).verdict == GateVerdict.PASSIVE, label
        assert vp.decide_band(H, "1:10").verdict == GateVerdict.NOT_PASSIVE, label
    # also through from_python, as the issue wrote it
    control = pytest.importorskip("control")
    d = vp.decide_band(vp.from_python(control.tf(NUM, DEN)), (0, 1.5))
    assert d.verdict == GateVerdict.PASSIVE and d.band == (0, Fraction(3, 2))


def test_whole_axis_decision_with_witness_and_margin():
    d = vp.decide((NUM, DEN))
    assert d.verdict == GateVerdict.NOT_PASSIVE and d.witness.data["omega"] == "5/2"
    assert vp.decide(([1], [1, 1])).verdict == GateVerdict.PASSIVE
    # H = 1 + 1/(s+1) has nu >= 1 everywhere: margin 1 holds, margin "1.1" does not
    assert vp.decide(([1, 2], [1, 1]), margin=1).verdict == GateVerdict.PASSIVE
    assert vp.decide(([1, 2], [1, 1]), margin="1.1").verdict == GateVerdict.NOT_PASSIVE


def test_static_gains_and_paths():
    assert vp.decide(np.eye(2)).verdict == GateVerdict.PASSIVE
    assert vp.decide(-1).verdict == GateVerdict.NOT_PASSIVE
    model = vp.as_model("verify/data/models/example_state_space.toml")
    assert model.n == 2 and vp.as_model(model) is model


def test_nu_and_relative_index_agree_on_sign():
    """R(w) <= 1 exactly where nu(w) >= 0, and both match hand values for 1/(s+1)."""
    w = np.geomspace(1e-2, 1e2, 200)
    n, r = vp.nu((NUM, DEN), w), vp.relative_index((NUM, DEN), w)
    far = np.abs(n) > 1e-9
    assert np.array_equal((n >= 0)[far], (r <= 1)[far])
    assert (n < 0).any() and (n > 0).any()
    first = vp.nu(([1], [1, 1]), [0, 1, 3])
    assert np.allclose(first, [1, 1 / 2, 1 / 10])
    # 1/(s+1): (1 - H)/(1 + H) = s/(s + 2), |.| = w / sqrt(w^2 + 4)
    assert np.allclose(vp.relative_index(([1], [1, 1]), [0, 2]), [0, 2 / np.sqrt(8)])


def test_indices_are_exported_and_exact():
    nu_ifp, rho_ofp = vp.passivity_indices(([1], [1, 1]))
    assert nu_ifp.exact and nu_ifp.lower == 0
    assert rho_ofp.exact and rho_ofp.lower == 1
    assert vp.ifp_index(([1, 2], [1, 1])).lower == 1
    assert isinstance(vp.ofp_index(([1, 2], [1, 1])), vp.IndexBounds)


BAD_MODELS = [
    None, object(), {}, "no/such/file.toml", ([1, 2],), (1, 2, 3), ([1], [0]),
    ([[1]], [1, 2]), np.zeros((2, 3)), (np.eye(2), np.eye(2), np.eye(2)),
    ([float("nan")], [1, 1]), ([1], [1, float("inf")]), ([1, 0, 0], [1, 1]),
    ("a", "b"), (np.eye(2), [[1]], [[1]], [[0]]), True, "",
]


@pytest.mark.parametrize("bad", BAD_MODELS, ids=range(len(BAD_MODELS)))
@pytest.mark.parametrize("call", ["decide", "decide_band", "nu", "relative_index",
                                  "ifp_index", "ofp_index", "passivity_indices"])
def test_bad_models_give_one_line(bad, call):
    args = {"decide_band": ((0, 1),), "nu": ([1.0],), "relative_index": ([1.0],)}
    with pytest.raises(VerifyInputError) as info:
        getattr(vp, call)(bad, *args.get(call, ()))
    text = str(info.value)
    assert text and "\n" not in text


def test_discrete_time_objects_are_refused():
    control = pytest.importorskip("control")
    with pytest.raises(VerifyInputError, match="discrete-time"):
        vp.decide(control.tf([1], [1, 0.5], 0.1))


BAD_BANDS = [None, 1.5, (1,), (0, 1, 2), (1, 0), (0, 0), (-1, 1), (0, float("nan")),
             (0, float("inf")), (True, 2), ("a", 1), "1", "0:x", "2:1", (0, 1e13), {0: 1}]


@pytest.mark.parametrize("band", BAD_BANDS, ids=range(len(BAD_BANDS)))
def test_bad_bands_give_one_line(band):
    with pytest.raises(VerifyInputError) as info:
        vp.decide_band((NUM, DEN), band)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("margin", ["x", None, float("nan"), True, [1], "1e99999"])
def test_bad_margins_give_one_line(margin):
    with pytest.raises(VerifyInputError) as info:
        vp.decide((NUM, DEN), margin=margin)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("omega", ["x", [[1, 2], [3, 4]], [float("nan")], None])
def test_bad_frequencies_give_one_line(omega):
    for f in (vp.nu, vp.relative_index):
        with pytest.raises(VerifyInputError) as info:
            f((NUM, DEN), omega)
        assert "\n" not in str(info.value)


def test_band_numbers_are_exact():
    """A float band edge is its binary value; a string is the decimal it spells."""
    assert vp.decide_band(([1], [1, 1]), (0, 0.1)).band[1] == Fraction(0.1)
    assert vp.decide_band(([1], [1, 1]), ("0", "0.1")).band[1] == Fraction(1, 10)


def test_search_floor_is_not_shown_as_a_bound():
    """rho_OFP of a model whose every loop down to the search's floor is unstable: the
    line says the index is at most the floor and that nothing lower was tried."""
    index = vp.ofp_index("verify/data/models/reconstructed_ks2p5.toml")
    if index.search_floor is None:
        pytest.skip("this model's OFP search found a certified value")
    text = index.summary()
    assert f"ρ_OFP ≤ {index.search_floor}" in text and "may be lower still" in text
    assert "upper bound -1000000" not in text


def test_the_sdp_range_end_is_not_an_estimate():
    """H = 0 has rho_OFP = +inf (y = 0): the SDP stops at the end of its range, 10^6,
    which is reported as a certified lower bound and a range end, never as '≈ 1e+06'."""
    index = vp.ofp_index(0)
    text = index.summary()
    assert index.estimate is None and index.lower == 10**6 and index.upper is None
    assert "≈" not in text and "may be larger, up to +∞" in text
