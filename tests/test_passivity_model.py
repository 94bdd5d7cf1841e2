"""Model input for the passivity gate (Section 4 human models): files, objects, realisation."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from verify.errors import VerifyInputError
from verify.passivity.io.model_file import load_model
from verify.passivity.model import (
    LTIModel,
    from_python,
    from_state_space,
    from_transfer_function,
)

SS_EXAMPLE = """
[state_space]            # continuous time
A = [[-1.0, 0.0], [0.0, -2.0]]
B = [[1.0], [1.0]]
C = [[1.0, 1.0]]
D = [[0.0]]
"""

TF_EXAMPLE = """
[transfer_function]      # element (i, j): descending powers of s
num = [[[1.2, 0.8], [0.05]], [[-0.05], [1.2, 0.8]]]
den = [[[1.0, 2.0, 1.5], [1.0]], [[1.0], [1.0, 2.0, 1.5]]]
"""
TF_NUM = [[[1.2, 0.8], [0.05]], [[-0.05], [1.2, 0.8]]]
TF_DEN = [[[1.0, 2.0, 1.5], [1.0]], [[1.0], [1.0, 2.0, 1.5]]]

OMEGA = np.array([0.0, 0.013, 0.4, 1.0, 1.7, 25.0, 900.0])


def direct(num, den, omega):
    """H(j w) by evaluating the polynomials of every element."""
    s = 1j * np.asarray(omega, dtype=float)
    m = len(num)
    return np.stack(
        [
            np.array(
                [
                    [np.polyval(num[i][j], x) / np.polyval(den[i][j], x) for j in range(m)]
                    for i in range(m)
                ]
            )
            for x in s
        ]
    )


def assert_matches(model, num, den, omega=OMEGA, rtol=1e-10):
    got = model.frequency_response(omega)
    want = direct(num, den, omega)
    err = np.linalg.norm(got - want, axis=(1, 2)) / np.linalg.norm(want, axis=(1, 2))
    assert err.max() < rtol, err


def write(tmp_path, text, name="model.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def assert_one_line_error(call, *fragments):
    with pytest.raises(VerifyInputError) as info:
        call()
    message = str(info.value)
    assert "\n" not in message
    for fragment in fragments:
        assert fragment in message, message
    return message


# --------------------------------------------------------------------------- example files


def test_state_space_example_file(tmp_path):
    path = write(tmp_path, 'name = "two lags"\nk_s = 2.5\nreconstructed = true\n' + SS_EXAMPLE)
    model = load_model(path)
    assert (model.n, model.m) == (2, 1)
    assert model.name == "two lags" and model.source == str(path)
    assert model.meta == {"k_s": 2.5, "reconstructed": True}
    assert model.realization == "state space as given"
    # H = 1/(s+1) + 1/(s+2) = (2s + 3)/(s^2 + 3s + 2)
    assert_matches(model, [[[2.0, 3.0]]], [[[1.0, 3.0, 2.0]]])


def test_transfer_function_example_file_is_minimal(tmp_path):
    model = load_model(write(tmp_path, TF_EXAMPLE, "human.toml"))
    assert model.name == "human"
    # Two second-order diagonal elements, constant off-diagonals: McMillan degree 4.
    assert (model.n, model.m) == (4, 2)
    assert model.realization.startswith("exact minimal realisation")
    assert_matches(model, TF_NUM, TF_DEN)
    assert np.allclose(model.D, [[0.0, 0.05], [-0.05, 0.0]])


def test_model_matrices_are_read_only(tmp_path):
    model = load_model(write(tmp_path, SS_EXAMPLE))
    assert model.A.dtype == np.float64
    with pytest.raises(ValueError):
        model.A[0, 0] = 5.0


def test_metadata_keys(tmp_path):
    text = 'description = "fitted"\nunits = "N m / rad"\nk_s = 3\n' + SS_EXAMPLE
    model = load_model(write(tmp_path, text))
    assert model.meta == {"description": "fitted", "units": "N m / rad", "k_s": 3.0}


def test_empty_state_space_file(tmp_path):
    text = "[state_space]\nA = []\nB = []\nC = []\nD = [[1.0, 0.5], [-0.5, 2.0]]\n"
    model = load_model(write(tmp_path, text))
    assert (model.n, model.m) == (0, 2)
    H = model.frequency_response(np.array([0.0, 3.0]))
    assert H.shape == (2, 2, 2) and np.all(H == model.D)


# --------------------------------------------------------------------------- minimality


@pytest.mark.parametrize(
    ("num", "den", "n"),
    [
        # pole-zero cancellation: (s+1)/((s+1)(s+2)) = 1/(s+2)
        ([[[1.0, 1.0]]], [[[1.0, 3.0, 2.0]]], 1),
        # common pole in column 0 (residue rank 1): degree 2, the stack has 3 states
        ([[[1.0], [1.0]], [[2.0], [0.0]]], [[[1.0, 1.0], [1.0, 2.0]], [[1.0, 1.0], [1.0]]], 2),
        # common pole in row 0 (removed on the observability side)
        ([[[1.0], [3.0]], [[0.0], [1.0]]], [[[1.0, 1.0], [1.0, 1.0]], [[1.0], [1.0, 2.0]]], 2),
        # the same pole on the diagonal has residue of rank 2: nothing may be removed
        ([[[1.0], [0.0]], [[0.0], [1.0]]], [[[1.0, 1.0], [1.0]], [[1.0], [1.0, 1.0]]], 2),
        # zero at the origin lands on the check grid: not a false alarm
        ([[[1.0, 0.0]]], [[[1.0, 1.0]]], 1),
        # integrator and a lightly damped resonance with a notch
        ([[[1.0, 0.0, 1.0]]], [[[1.0, 0.01, 1.0, 0.0]]], 3),
        # leading zeros are ignored; badly scaled 4th-order lag (poles at 1e3)
        ([[[0.0, 0.0, 1e12]]], [[[1.0, 4e3, 6e6, 4e9, 1e12]]], 4),
    ],
)
def test_minimal_realisation(num, den, n):
    model = from_transfer_function(num, den)
    assert model.n == n
    assert_matches(model, num, den, omega=np.array([0.05, 0.3, 2.0, 7.0, 4000.0]))


def test_static_gain_has_no_states():
    model = from_transfer_function(
        [[[2.0], [0.0]], [[1.0, 1.0], [3.0]]], [[[4.0], [1.0]], [[2.0, 2.0], [1.0]]]
    )
    assert (model.n, model.m) == (0, 2)
    assert np.array_equal(model.D, [[0.5, 0.0], [0.5, 3.0]])


def test_frequency_response_shapes_and_values():
    model = from_state_space([[-2.0]], [[1.0, 0.0]], [[3.0], [0.0]], [[0.0, 1.0], [1.0, 0.0]])
    H = model.frequency_response([0.0, 2.0])
    assert H.shape == (2, 2, 2) and H.dtype == complex
    assert np.allclose(H[:, 0, 0], 3.0 / (2.0 + 1j * np.array([0.0, 2.0])), rtol=1e-15)
    assert np.allclose(H[:, 0, 1], 1.0) and np.allclose(H[:, 1, 1], 0.0)
    assert model.frequency_response(np.zeros(0)).shape == (0, 2, 2)
    assert_one_line_error(lambda: model.frequency_response([np.nan]), "NaN")


def test_frequency_response_at_a_pole_is_an_input_error():
    model = from_transfer_function([[[1.0]]], [[[1.0, 0.0, 4.0]]])  # poles at +-2j
    assert_one_line_error(lambda: model.frequency_response(np.array([1.0, 2.0])), "pole")


# --------------------------------------------------------------------------- python objects


def test_python_control_objects():
    control = pytest.importorskip("control")
    ss = control.ss([[-1.0, 0.0], [0.0, -2.0]], [[1.0], [1.0]], [[1.0, 1.0]], [[0.0]])
    model = from_python(ss, name="ss")
    assert (model.name, model.n, model.m) == ("ss", 2, 1)
    assert_matches(model, [[[2.0, 3.0]]], [[[1.0, 3.0, 2.0]]])

    tf = control.tf(TF_NUM, TF_DEN)
    model = from_python(tf)
    assert (model.n, model.m) == (4, 2)
    assert_matches(model, TF_NUM, TF_DEN)

    static = from_python(control.ss([], [], [], [[2.0]]))
    assert (static.n, static.m) == (0, 1)

    assert_one_line_error(lambda: from_python(control.tf([1.0], [1.0, 0.5], 0.1)), "discrete")
    assert_one_line_error(
        lambda: from_python(control.tf([[[1.0], [1.0]]], [[[1.0, 1.0], [1.0, 2.0]]])), "square"
    )


def test_scipy_signal_objects():
    num, den = [[[1.0, 3.0]]], [[[1.0, 3.0, 2.0]]]
    for obj in (
        signal.lti([1.0, 3.0], [1.0, 3.0, 2.0]),
        signal.TransferFunction([1.0, 3.0], [1.0, 3.0, 2.0]),
        signal.ZerosPolesGain([-3.0], [-1.0, -2.0], 1.0),
        signal.StateSpace(*signal.tf2ss([1.0, 3.0], [1.0, 3.0, 2.0])),
    ):
        model = from_python(obj, name="scipy")
        assert (model.n, model.m) == (2, 1), type(obj)
        assert_matches(model, num, den)
    model = from_python(signal.lti([1.0, 1.0], [1.0, 3.0, 2.0]))
    assert model.n == 1  # the cancellation (s+1)/((s+1)(s+2)) is removed
    assert_one_line_error(
        lambda: from_python(signal.StateSpace([[0.5]], [[1.0]], [[1.0]], [[0.0]], dt=0.1)),
        "discrete",
    )
    assert_one_line_error(
        lambda: from_python(signal.TransferFunction([[1.0], [2.0]], [1.0, 1.0])), "square"
    )
    assert_one_line_error(lambda: from_python("1/(s+1)"), "cannot convert")


def test_from_python_passes_an_lti_model_through():
    model = from_state_space([[-1.0]], [[1.0]], [[1.0]], [[0.0]], name="a")
    assert from_python(model) is model
    renamed = from_python(model, name="b")
    assert renamed.name == "b" and np.array_equal(renamed.A, model.A)


# --------------------------------------------------------------------------- bad input (Python)


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (([["x"]], [[1.0]], [[1.0]], [[0.0]]), "expected a real number"),
        (([[True]], [[1.0]], [[1.0]], [[0.0]]), "expected a real number"),
        (([[None]], [[1.0]], [[1.0]], [[0.0]]), "expected a real number"),
        (([[1j]], [[1.0]], [[1.0]], [[0.0]]), "expected a real number"),
        (([[np.nan]], [[1.0]], [[1.0]], [[0.0]]), "NaN or Inf"),
        ((np.array([[np.inf]]), [[1.0]], [[1.0]], [[0.0]]), "NaN or Inf"),
        (([[-1.0]], [[1.0, 1.0]], [[1.0]], [[0.0, 0.0]]), "square"),
        (([[-1.0]], [[1.0, 1.0]], [[1.0], [1.0]], [[0.0]]), "B: expected shape (1, 1)"),
        (([[-1.0]], [[1.0]], [[1.0], [1.0]], [[0.0]]), "square"),
        (([[-1.0, 0.0]], [[1.0]], [[1.0]], [[0.0]]), "A: expected a square"),
        (([[-1.0, 0.0], [0.0]], [[1.0]], [[1.0]], [[0.0]]), "ragged"),
        (([], [[1.0]], [], [[0.0]]), "B: expected shape (0, 1)"),
        (([], [], [], []), "D: expected an m x m matrix"),
    ],
)
def test_bad_state_space(args, fragment):
    assert_one_line_error(lambda: from_state_space(*args), fragment)


def test_lti_model_validates_on_construction():
    assert_one_line_error(lambda: LTIModel("x", [[1.0]], [[1.0]], [[1.0]], [[np.nan]]), "NaN")


@pytest.mark.parametrize(
    ("num", "den", "fragment"),
    [
        ([[[1.0]]], [[[0.0, 0.0]]], "zero denominator"),
        ([[[1.0, 0.0, 0.0]]], [[[1.0, 1.0]]], "improper"),
        ([[[0.0, 1.0, 1.0]]], [[[0.0, 0.0, 1.0]]], "improper"),  # leading zeros stripped
        ([[[1.0], [1.0]]], [[[1.0, 1.0], [1.0, 2.0]]], "square"),
        ([[[1.0]]], [[[1.0, 1.0]], [[1.0]]], "same m x m nesting"),
        ([[1.0]], [[[1.0, 1.0]]], "nesting too shallow"),
        ([[[[1.0]]]], [[[1.0, 1.0]]], "nesting too deep"),
        ([[[]]], [[[1.0, 1.0]]], "empty coefficient list"),
        ([[["1"]]], [[[1.0, 1.0]]], "expected a real number"),
        ([[[float("nan")]]], [[[1.0, 1.0]]], "NaN or Inf"),
        ([[[1.0], [1.0]], [[1.0]]], [[[1.0], [1.0]], [[1.0]]], "rows of different lengths"),
        ([], [], "expected num[i][j]"),
    ],
)
def test_bad_transfer_function(num, den, fragment):
    assert_one_line_error(lambda: from_transfer_function(num, den), fragment)


# --------------------------------------------------------------------------- bad input (files)


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        (SS_EXAMPLE.replace("-2.0", '"-2.0"'), "expected a real number, got str"),
        (SS_EXAMPLE.replace("-2.0", "true"), "expected a real number, got bool"),
        (SS_EXAMPLE.replace("-2.0", "nan"), "NaN or Inf"),
        (SS_EXAMPLE.replace("-2.0", "-inf"), "NaN or Inf"),
        (SS_EXAMPLE.replace("D = [[0.0]]", "D = [[0.0, 0.0]]"), "square"),
        (SS_EXAMPLE.replace("D = [[0.0]]", "D = [[0.0]]\nE = [[0.0]]"), "unknown key(s) E"),
        (SS_EXAMPLE.replace("D = [[0.0]]\n", ""), "missing key(s) D"),
        ("colour = 1\n" + SS_EXAMPLE, "unknown key(s) colour"),
        (SS_EXAMPLE + TF_EXAMPLE, "both are present"),
        ('name = "x"\n', "neither is present"),
        ("state_space = 3\n", "must be a table"),
        ("name = 3\n" + SS_EXAMPLE, "'name' must be a string"),
        ("k_s = 0\n" + SS_EXAMPLE, "'k_s' must be a number > 0"),
        ("k_s = nan\n" + SS_EXAMPLE, "'k_s': NaN or Inf is not allowed"),
        ('k_s = "2"\n' + SS_EXAMPLE, "'k_s': expected a real number, got str '2'"),
        ('reconstructed = "yes"\n' + SS_EXAMPLE, "'reconstructed' must be true or false"),
        (TF_EXAMPLE.replace("[1.0, 2.0, 1.5], [1.0]]", "[0.0, 0.0], [1.0]]"), "zero denominator"),
        (TF_EXAMPLE.replace("[[1.2, 0.8], [0.05]]", "[[1.2, 0.8, 1.0, 2.0], [0.05]]"), "improper"),
        (
            "[transfer_function]\nnum = [[[1.0], [0.0]]]\n"
            "den = [[[1.0, 1.0], [1.0]], [[1.0], [1.0, 1.0]]]\n",
            "same m x m nesting",
        ),
        (
            "[transfer_function]\nnum = [[[1.0], [2.0]]]\nden = [[[1.0, 1.0], [1.0]]]\n",
            "must be square",
        ),
        (TF_EXAMPLE.replace("[[1.2, 0.8], [0.05]]", "[1.2, 0.8]"), "nesting"),
        (TF_EXAMPLE.replace("den =", "denominator ="), "unknown key(s) denominator"),
        ("[transfer_function\n", "not valid TOML"),
    ],
)
def test_bad_model_file(tmp_path, text, fragment):
    path = write(tmp_path, text)
    message = assert_one_line_error(lambda: load_model(path), fragment)
    assert message.startswith(str(path))


def test_missing_file(tmp_path):
    path = tmp_path / "nope.toml"
    message = assert_one_line_error(lambda: load_model(path), "cannot read")
    assert message.startswith(str(path))



def test_one_ulp_of_dynamics_is_kept():
    # num = 2 den + one ulp s: a float denotes its exact binary value, so the exact
    # realisation keeps the (tiny) dynamic part instead of calling it rounding noise.
    model = from_transfer_function([[[2.0, 4.000000000000001, 6.0]]], [[[1.0, 2.0, 3.0]]])
    assert model.n == 2 and model.D[0, 0] == 2.0


def test_small_gain_keeps_its_states():
    num, den = [[[1e-12], [0.0]], [[0.0], [3e-9, 0.0]]], [[[1.0, 1.0], [1.0]], [[1.0], [1.0, 5.0]]]
    model = from_transfer_function(num, den)
    assert model.n == 2
    assert_matches(model, num, den)
