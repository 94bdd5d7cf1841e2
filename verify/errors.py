"""Errors that mean "the input is bad", reported by the CLI in one line with exit code 2."""


class VerifyInputError(ValueError):
    """Input that cannot be checked: wrong shape, non-finite numbers, malformed files."""


class NotARotationError(VerifyInputError):
    """A matrix that should lie in SO(3) does not (orthogonality or determinant fails)."""


class DbarUndefinedError(VerifyInputError):
    """The average direction dbar = sum d_i / |sum d_i| (paper, Section 2) is undefined.

    It needs sum d_i != 0; near zero the direction is numerically meaningless.
    """

