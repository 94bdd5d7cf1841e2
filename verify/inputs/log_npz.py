"""Reading the NPZ form of an experiment log (format: :mod:`verify.inputs.experiment_log`).

The archive's sizes are judged before any data is decompressed: the zip directory's
uncompressed sizes (at most ``MAX_NPZ_BYTES`` in all) and each member's .npy header
(shape and dtype, which must fit in the member). Arrays are then loaded without pickle.
"""

from __future__ import annotations

import lzma
import math
import zipfile
import zlib
from pathlib import Path
from typing import BinaryIO

import numpy as np

from verify.errors import VerifyInputError
from verify.inputs.log_checks import (
    COLUMNS,
    FLAGS,
    INTEGER_COLUMNS,
    MAX_NPZ_BYTES,
    MAX_TRIAL_ID,
    MIN_STEP,
    REQUIRED,
    check_header,
    check_limits,
    fail,
    short,
)

#: What a damaged archive raises while it is read (zlib and lzma report corrupt streams
#: with their own error types; bz2 with OSError).
_ARCHIVE_ERRORS = (OSError, ValueError, zipfile.BadZipFile, EOFError, RuntimeError,
                   NotImplementedError, zlib.error, lzma.LZMAError)


def read_npz(path: Path, handle: BinaryIO) -> tuple[dict[str, np.ndarray], float | None]:
    """The columns of an NPZ archive, sizes checked from the headers before any data is
    decompressed (the zip directory's uncompressed sizes, each member's .npy header)."""
    magic = handle.read(6)
    handle.seek(0)
    if magic == b"\x93NUMPY":
        raise VerifyInputError(f"{path}: a single .npy array, not an .npz archive; save the "
                               "columns with numpy.savez(path, time=..., trial=..., ...)")
    try:
        archive = zipfile.ZipFile(handle)
    except _ARCHIVE_ERRORS as exc:
        first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise VerifyInputError(f"{path}: not a readable .npz archive ({first}); write it with "
                               "numpy.savez or verify simulate --log") from None
    with archive:
        infos = archive.infolist()
        names = [info.filename for info in infos]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise VerifyInputError(f"{path}: the archive holds {short(twice[0])!r} twice "
                                   "(ambiguous); rewrite it with numpy.savez")
        if not infos:
            raise VerifyInputError(f"{path}: empty archive; it needs the arrays "
                                   f"{', '.join(REQUIRED)}")
        total = sum(info.file_size for info in infos)
        if total > MAX_NPZ_BYTES or len(infos) > 2 * len(COLUMNS):
            raise VerifyInputError(
                f"{path}: the archive holds {len(infos)} member(s) of {total} bytes "
                f"uncompressed, above the limit of {MAX_NPZ_BYTES // 2**20} MiB (or "
                f"{2 * len(COLUMNS)} members); split the log into several files")
        headers: dict[str, tuple[tuple[int, ...], np.dtype, zipfile.ZipInfo]] = {}
        for info in infos:
            name = info.filename.removesuffix(".npy")
            try:
                with archive.open(info) as member:
                    version = np.lib.format.read_magic(member)
                    if version == (1, 0):
                        shape, _, dtype = np.lib.format.read_array_header_1_0(member)
                    else:
                        shape, _, dtype = np.lib.format.read_array_header_2_0(member)
            except _ARCHIVE_ERRORS as exc:
                raise VerifyInputError(f"{path}: array {short(name)!r} is unreadable "
                                       f"({short(' '.join(str(exc).split()), 80)}); rewrite "
                                       "the archive") from None
            if dtype.hasobject:
                raise VerifyInputError(
                    f"{path}: array {short(name)!r} holds Python objects (pickled), which are "
                    "not loaded; store numbers (float64, int64 or bool)")
            if math.prod(shape) * dtype.itemsize > info.file_size:
                raise VerifyInputError(f"{path}: array {short(name)!r}: its header promises "
                                       f"{math.prod(shape) * dtype.itemsize} bytes, the member "
                                       f"holds {info.file_size}; rewrite the archive")
            headers[name] = (shape, dtype, info)
        rate = None
        if "rate" in headers:
            shape, dtype, _ = headers["rate"]
            if shape != () or dtype.kind not in "iuf":
                raise fail(f"{path}: array 'rate'", f"must be one positive number (0-d "
                           f"array), got shape {shape}, dtype {dtype}")
        check_header(str(path), [n for n in headers if n != "rate"], f"{path}")
        shapes = {n: s for n, (s, _, _) in headers.items() if n != "rate"}
        for name, shape in shapes.items():
            if len(shape) != 1:
                raise fail(f"{path}: array {name!r}", f"must be 1-D (one value per sample), "
                           f"got shape {shape}")
        if len(set(shapes.values())) > 1:
            raise fail(str(path), "arrays of different lengths "
                       + ", ".join(f"{n}: {s[0]}" for n, s in shapes.items())
                       + "; give every column one value per sample")
        if next(iter(shapes.values()))[0] == 0:
            raise VerifyInputError(f"{path}: the log has no samples; add data")
        arrays: dict[str, np.ndarray] = {}
        for name, (_, _, info) in headers.items():
            try:
                with archive.open(info) as member:
                    arrays[name] = np.lib.format.read_array(member, allow_pickle=False)
            except _ARCHIVE_ERRORS as exc:
                raise VerifyInputError(f"{path}: array {name!r} is unreadable "
                                       f"({short(' '.join(str(exc).split()), 80)}); rewrite "
                                       "the archive") from None
    if "rate" in arrays:
        r = arrays.pop("rate")
        if not (np.isfinite(r) and 0 < r <= 1 / MIN_STEP):
            raise fail(f"{path}: array 'rate'", f"must be one positive number of at most "
                       f"{1 / MIN_STEP:g} Hz, got {r}")
        rate = float(r)
    return npz_columns(path, arrays), rate


def npz_columns(path: Path, arrays: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    columns: dict[str, np.ndarray] = {}
    for name, arr in arrays.items():
        where = f"{path}: array {name!r}"
        kind = arr.dtype.kind
        if name in INTEGER_COLUMNS:
            if kind == "b" and name in FLAGS:
                arr = arr.astype(np.int64)
            elif kind not in "iu":
                raise fail(where, f"dtype {arr.dtype} is not an integer type; store whole "
                           "numbers as int64" + (" (or bool)" if name in FLAGS else ""))
            big = np.flatnonzero(np.abs(arr.astype(np.float64)) > MAX_TRIAL_ID)
            if big.size:
                raise fail(f"{where}[{big[0]}]", f"{arr[big[0]]} exceeds the limit "
                           f"{MAX_TRIAL_ID} in size; number the trials 0, 1, 2, ...")
            columns[name] = arr.astype(np.int64)
        else:
            if kind not in "iuf":
                raise fail(where, f"dtype {arr.dtype} is not a real number type; store float64")
            arr = arr.astype(np.float64)
            bad = np.flatnonzero(~np.isfinite(arr))
            if bad.size:
                raise fail(f"{where}[{bad[0]}]", f"NaN or Inf ({arr[bad[0]]}) is not allowed; "
                           "give a finite number or mark the sample invalid (valid = 0)")
            check_limits(name, arr, where)
            columns[name] = arr
    return columns


__all__ = ["read_npz"]
