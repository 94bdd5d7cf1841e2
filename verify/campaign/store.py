"""The result store: a Parquet dataset of one row per run key, grown by atomic part files.

The store is a folder of ``part-*.parquet`` files with one schema (:data:`SCHEMA`). Rows
are appended as a new part file written to a temporary name and renamed into place, so a
reader sees a part whole or not at all, and a crash or a kill loses at most the rows not
yet appended. Appending is idempotent per key: rows whose key is already stored (by this
writer or in an earlier part) are dropped, so a run computed twice (a retried task, a
resumed campaign) is stored once. Reading merges the parts and keeps the first row of a
key in part-name order (parts are named by time), which also settles the rare case of
two writers on one folder.

``campaign.json`` in the folder names the campaign the store belongs to (the spec's
fingerprint, :func:`verify.campaign.runs.spec_fingerprint`, and name): it is written
with the first part, and a store of another campaign is refused before any run.
"""

from __future__ import annotations

import json
import time
import uuid
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import pyarrow as pa
import pyarrow.parquet as pq

from verify.artefacts.atomic import write_atomic
from verify.campaign.execute import column
from verify.errors import VerifyInputError
from verify.inputs.campaign_spec import PROPERTIES

_PROPERTY_FIELDS = [f for p in PROPERTIES for f in (
    pa.field(column(p), pa.string()), pa.field(f"{column(p)}_violation", pa.float64()),
    pa.field(f"{column(p)}_tolerance", pa.float64()),
    pa.field(f"{column(p)}_conclusion", pa.string()))]

SCHEMA = pa.schema([
    pa.field("key", pa.string(), nullable=False),
    pa.field("human", pa.string()), pa.field("human_kind", pa.string()),
    pa.field("human_sha256", pa.string()), pa.field("human_gain", pa.float64()),
    pa.field("human_gate", pa.string()),
    pa.field("engine", pa.string()), pa.field("engine_note", pa.string()),
    pa.field("k_s", pa.float64()), pa.field("n", pa.int64()), pa.field("seed", pa.int64()),
    pa.field("autonomous", pa.string()), pa.field("reference", pa.string()),
    pa.field("seconds", pa.float64()), pa.field("step", pa.float64()),
    pa.field("convergence_threshold", pa.float64()),
    *_PROPERTY_FIELDS,
    pa.field("convergence_time", pa.float64()), pa.field("dbar_error_end", pa.float64()),
    pa.field("min_tr_Rbar_r", pa.float64()), pa.field("max_V_rise", pa.float64()),
    pa.field("supply_end", pa.float64()), pa.field("uses_storage", pa.bool_()),
    pa.field("wall_time", pa.float64()), pa.field("worker", pa.string()),
    pa.field("error", pa.string()),
])


class ResultStore:
    """The Parquet dataset in ``folder`` (created on the first append)."""

    def __init__(self, folder: str | Path) -> None:
        self.folder = Path(folder)
        if self.folder.exists() and not self.folder.is_dir():
            raise VerifyInputError(f"{self.folder}: the result store must be a folder")
        self._keys: set[str] | None = None
        self._record: dict[str, str] | None = None  # campaign.json to write (bind)

    MANIFEST = "campaign.json"

    def bind(self, fingerprint: str, name: str) -> None:
        """Tie the store to one campaign: record ``fingerprint`` in an empty store, and
        refuse (one line, before any run) a store that belongs to another campaign or
        holds rows with no record of their campaign."""
        manifest = self.folder / self.MANIFEST
        if manifest.is_file():
            try:
                found = json.loads(manifest.read_text(encoding="utf-8"))
                theirs, their_name = str(found["spec_fingerprint"]), str(found["name"])
            except (OSError, ValueError, KeyError, TypeError, UnicodeDecodeError):
                raise VerifyInputError(f"{manifest}: not a readable campaign record; this "
                                       "folder was not written by verify campaign: choose "
                                       "another --out") from None
            if theirs != fingerprint:
                raise VerifyInputError(
                    f"{self.folder} holds the store of another campaign ({their_name!r}, "
                    f"spec fingerprint {theirs}; this spec's is {fingerprint}): choose "
                    "another --out")
            return
        if manifest.exists():
            raise VerifyInputError(f"{manifest}: not a regular file; choose another --out")
        if self.parts():
            raise VerifyInputError(f"{self.folder} holds rows with no record of their "
                                   f"campaign ({self.MANIFEST} is missing): choose another "
                                   "--out")
        # written with the first rows, so that a refused or failed start leaves nothing
        self._record = {"spec_fingerprint": fingerprint, "name": name}

    def parts(self) -> list[Path]:
        """The part files, in the order they were written."""
        if not self.folder.is_dir():
            return []
        return sorted(self.folder.glob("part-*.parquet"))

    def keys(self) -> set[str]:
        """The run keys already stored."""
        if self._keys is None:
            keys: set[str] = set()
            for part in self.parts():
                keys.update(self._read(part, ["key"]).column("key").to_pylist())
            self._keys = keys
        return set(self._keys)

    def _read(self, part: Path, columns: list[str] | None = None) -> pa.Table:
        try:
            return pq.read_table(part, columns=columns, schema=SCHEMA)
        except (OSError, pa.ArrowException) as exc:
            raise VerifyInputError(f"{part}: not a readable part of a campaign store "
                                   f"({' '.join(str(exc).split())}); move it away") from None

    def append(self, rows: Iterable[dict[str, Any]]) -> int:
        """Store the rows whose key is new, as one part file; returns how many."""
        stored = self.keys()
        fresh: list[dict[str, Any]] = []
        for row in rows:
            if row["key"] not in stored:
                stored.add(row["key"])
                fresh.append(row)
        if not fresh:
            return 0
        table = pa.Table.from_pylist([{f.name: r.get(f.name) for f in SCHEMA} for r in fresh],
                                     schema=SCHEMA)
        self.folder.mkdir(parents=True, exist_ok=True)
        manifest = self.folder / self.MANIFEST
        if self._record is not None and not manifest.exists():
            write_atomic(manifest, json.dumps(self._record, sort_keys=True, indent=1) + "\n")
        name = f"part-{time.time_ns():020d}-{uuid.uuid4().hex[:8]}.parquet"
        sink = pa.BufferOutputStream()
        pq.write_table(table, sink)
        write_atomic(self.folder / name, sink.getvalue().to_pybytes())
        self._keys = stored
        return len(fresh)

    def rows(self, keys: Sequence[str] | None = None) -> list[dict[str, Any]]:
        """Every stored row (first of each key), or those of ``keys`` in that order."""
        seen: dict[str, dict[str, Any]] = {}
        for part in self.parts():
            for row in self._read(part).to_pylist():
                seen.setdefault(row["key"], row)
        if keys is None:
            return list(seen.values())
        return [seen[k] for k in keys if k in seen]

    def count(self) -> int:
        """Rows in the part files, duplicates included (for checks of the store)."""
        return sum(pq.ParquetFile(p).metadata.num_rows for p in self.parts())


__all__ = ["SCHEMA", "ResultStore"]
