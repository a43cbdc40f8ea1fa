"""One run directory (docs/case_format.md, "Run layout") as a Python object."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

# Every engine writes these two when a run starts; hull_force.csv follows when it ends and report.json
# after brash-post, so a running or failed run still loads (its .force then says what is missing). A run of an
# own LIGGGHTS deck has no meta.json: its case.yaml and an output of the deck's (the hull force record
# hull_force.raw of fix ave/time, dump custom files) make it a run too (docs/case_format.md, "A run from your
# own input").
REQUIRED_FILES = ("case.yaml", "meta.json")

FORCE_FILE = "hull_force.csv"
RAW_FORCE_FILE = "hull_force.raw"   # LIGGGHTS fix ave/time: '#' lines, then rows "TimeStep t fx fy fz"
DUMP_FIRST_LINE = "ITEM: TIMESTEP"  # LIGGGHTS dump custom, one file per snapshot
FORCE_COLUMNS = ("t_s", "fx_N", "fy_N", "fz_N")
# The hull force split (docs/physics.md "The hull force split"): fx by hull region, then by mechanism; each set
# adds up to fx_N. Written by LIGGGHTS and brash-ode; a record without them has no split (never zero).
SPLIT_COLUMNS = ("fx_bow_N", "fx_mid_N", "fx_stern_N", "fx_normal_N", "fx_tangential_N")
SPLIT_PARTS = ("bow", "mid", "stern", "normal", "tangential")
INDEX_FILE = Path("particles") / "index.csv"
INDEX_COLUMNS = ("step", "t_s", "file", "hull_x_m")
# the state column of a moving window's snapshots (docs/case_format.md, particles/)
PIECE_STATES = {0: "in the scene", 1: "held out", 2: "removed"}
REPORT_FILE = "report.json"


class RunError(Exception):
    """A run directory, or one of its files, is not what the run layout says."""


class NotARunError(RunError):
    """The folder is not a run directory (a file every run has is missing)."""


@dataclass(frozen=True)
class Resistance:
    """The resistance brash-post measured in the run's averaging window (report.json)."""

    mean_N: float                  # model scale, mean of -fx over the window
    ci95_N: float                  # its 95 % confidence half-width (block averaging)
    full_kN: float | None          # full scale (Froude scaling with ship.scale_lambda)
    full_ci95_kN: float | None
    window_s: tuple[float, float]  # the window actually averaged
    plateau_found: bool | None     # False: the CI is a lower bound (report.md says so)
    fsicr_R_CH_kN: float | None    # FSICR channel resistance of the measured hull
    ratio_fsicr_to_sim: float | None
    notes: tuple[str, ...] = field(default_factory=tuple)

    @property
    def rel_ci95(self) -> float:
        """ci95 / mean (inf for a zero mean)."""
        return self.ci95_N / abs(self.mean_N) if self.mean_N else math.inf

    def __str__(self) -> str:
        text = f"{self.mean_N:.4g} ± {self.ci95_N:.2g} N model"
        if self.full_kN is not None:
            ci = f" ± {self.full_ci95_kN:.3g}" if self.full_ci95_kN is not None else ""
            text += f", {self.full_kN:.4g}{ci} kN full scale"
        return text + f" (window {self.window_s[0]:g}-{self.window_s[1]:g} s)"


def load_run(path: str | Path) -> "Run":
    """Open the run directory PATH; raises NotARunError naming the first missing file."""
    return Run(path)


def _optional_float(value: Any) -> float | None:
    return None if value is None else float(value)


@dataclass(frozen=True)
class SplitPart:
    """One part of the hull force split: its resistance (-fx) over the window, as brash-post averages it."""

    mean_N: float
    ci95_N: float
    full_kN: float | None
    full_ci95_kN: float | None
    contact: bool = True  # False: the part touched no ice in the window (its 0 is "no contact")


@dataclass(frozen=True)
class ResistanceSplit:
    """Where the resistance comes from (report.json resistance_split_model_N): by hull region (bow, mid, stern)
    and by mechanism (normal, tangential); each set adds up to the resistance."""

    parts: dict[str, SplitPart]
    x_par_m: tuple[float, float] | None  # the parallel mid-body, hull frame (x = 0 at the aft perpendicular)

    def __getitem__(self, part: str) -> SplitPart:
        return self.parts[part]

    def __str__(self) -> str:
        return "; ".join(f"{name} {p.mean_N:.4g} ± {p.ci95_N:.2g} N" if p.contact else f"{name} no contact"
                         for name, p in self.parts.items())


class Run:
    """A run directory: meta.json, case.yaml, hull_force.csv, particles/, report.json.

    meta and case are read when the run is opened; force, snapshots and report on first use.
    """

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        if not self.path.exists():
            raise NotARunError(f"{self.path}: no such run directory")
        if not self.path.is_dir():
            raise NotARunError(f"{self.path}: not a folder (a run directory is a folder, docs/case_format.md)")
        for name in REQUIRED_FILES:
            if not (self.path / name).is_file():
                if name == "meta.json" and self._has_deck_output():
                    continue  # an own deck's run: engine and status unknown
                hint = ""
                if name == "meta.json" and (self.path / "case.yaml").is_file():
                    hint = " (a case folder? run it with an engine first: brash-ode / brash-liggghts-run)"
                raise NotARunError(f"{self.path} is not a run directory: {self.path / name} is missing{hint}")
        self.meta: dict = self._read_json("meta.json") if (self.path / "meta.json").is_file() else {}
        self.case: dict = self._read_yaml("case.yaml")

    def _has_deck_output(self) -> bool:
        """A hull force record or a dump custom file of an own deck beside its case.yaml."""
        return any((self.path / f).is_file() for f in (FORCE_FILE, RAW_FORCE_FILE)) or bool(self._native_dumps())

    def _native_dumps(self) -> list[Path]:
        """The folder's LIGGGHTS dump custom files (brash's own outputs and restart files left out)."""
        skip = {"particles", "paraview", "post", "restart"}
        found = []
        for f in sorted(self.path.rglob("*")):
            rel = f.relative_to(self.path)
            if len(rel.parts) > 1 and rel.parts[0] in skip or not f.is_file():
                continue
            try:
                with open(f, encoding="utf-8") as fh:
                    first = fh.readline().rstrip("\r\n")
            except (UnicodeDecodeError, OSError):
                continue
            if first == DUMP_FIRST_LINE:
                found.append(f)
        return found

    def __repr__(self) -> str:
        return (f"<brash run {self.path} engine={self.meta.get('engine')!r} "
                f"model={self.meta.get('fluid_model')!r} status={self.status!r}>")

    # ---- small files -------------------------------------------------------------------------------
    def _read_json(self, name: str) -> dict:
        file = self.path / name
        try:
            with open(file, encoding="utf-8") as f:
                data = json.load(f)
        except json.JSONDecodeError as e:
            raise RunError(f"{file}: not valid JSON (line {e.lineno}: {e.msg})") from e
        if not isinstance(data, dict):
            raise RunError(f"{file}: expected a JSON object, found {type(data).__name__}")
        return data

    def _read_yaml(self, name: str) -> dict:
        file = self.path / name
        try:
            with open(file, encoding="utf-8") as f:
                data = yaml.safe_load(f)
        except yaml.YAMLError as e:
            raise RunError(f"{file}: not valid YAML ({e})") from e
        if not isinstance(data, dict):
            raise RunError(f"{file}: expected a mapping of case keys, found {type(data).__name__}")
        return data

    def _read_csv(self, rel: Path | str, columns: tuple[str, ...], what: str) -> pd.DataFrame:
        file = self.path / rel
        if not file.is_file():
            raise RunError(f"{file} is missing ({what}; run status {self.status!r})")
        try:
            df = pd.read_csv(file)
        except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as e:
            raise RunError(f"{file}: not a readable CSV ({e})") from e
        missing = [c for c in columns if c not in df.columns]
        if missing:
            raise RunError(f"{file}: column(s) {', '.join(missing)} missing "
                           f"(header {','.join(map(str, df.columns))}; expected {','.join(columns)})")
        return df

    @property
    def status(self) -> str | None:
        """meta.json's status: running, complete or failed; "unknown" for a run without meta.json."""
        return self.meta.get("status", "unknown" if not self.meta else None)

    @property
    def name(self) -> str:
        return self.path.resolve().name

    # ---- hull force --------------------------------------------------------------------------------
    @cached_property
    def force(self) -> pd.DataFrame:
        """hull_force.csv (or an own deck's hull_force.raw): t_s, fx_N, fy_N, fz_N (force of the ice on the hull)
        plus resistance_N = -fx_N."""
        if not (self.path / FORCE_FILE).is_file() and (self.path / RAW_FORCE_FILE).is_file():
            df = self._read_raw_force()
        else:
            df = self._read_csv(FORCE_FILE, FORCE_COLUMNS,
                                "the engine writes it when the run ends: a running or killed run has none yet")
        for c in FORCE_COLUMNS:
            if not pd.api.types.is_numeric_dtype(df[c]):
                raise RunError(f"{self.path / FORCE_FILE}: column {c} is not numeric")
        df["resistance_N"] = -df["fx_N"]
        if self.has_split:
            for c in SPLIT_COLUMNS:
                if not pd.api.types.is_numeric_dtype(df[c]):
                    raise RunError(f"{self.path / FORCE_FILE}: column {c} is not numeric")
        return df

    @property
    def has_split(self) -> bool:
        """Whether hull_force.csv records the hull force split (every column of SPLIT_COLUMNS)."""
        file = self.path / FORCE_FILE
        if not file.is_file():
            return False
        with open(file, encoding="utf-8") as f:
            header = f.readline().strip().split(",")
        return all(c in header for c in SPLIT_COLUMNS)

    def _read_raw_force(self) -> pd.DataFrame:
        file = self.path / RAW_FORCE_FILE
        try:
            df = pd.read_csv(file, comment="#", sep=r"\s+", header=None)
        except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as e:
            raise RunError(f"{file}: not a readable fix ave/time record ({e})") from e
        if df.shape[1] != 5:
            raise RunError(f"{file}: {df.shape[1]} columns, expected 5 (TimeStep t fx fy fz of fix ave/time)")
        df = df.iloc[:, 1:]
        df.columns = list(FORCE_COLUMNS)
        return df

    # ---- particle snapshots ------------------------------------------------------------------------
    @cached_property
    def snapshots(self) -> pd.DataFrame:
        """particles/index.csv: step, t_s, file, hull_x_m (one row per snapshot, in time order).

        Without it, an own deck's dump custom files, timed as brash-post does: t_s = step x run.timestep_s, the
        hull at hull.start_x_m + ship.speed_m_s t_s (file: the path relative to the run folder)."""
        if (self.path / INDEX_FILE).is_file() or not self._native_dumps():
            return self._read_csv(INDEX_FILE, INDEX_COLUMNS, "the index of the particle snapshots")
        run, hull, ship = (self.case.get(k) or {} for k in ("run", "hull", "ship"))
        dt = run.get("timestep_s")
        if dt is None:
            raise RunError(f"{self.path / 'case.yaml'}: run.timestep_s is needed to time the dump custom files")
        rows = []
        for f in self._native_dumps():
            with open(f, encoding="utf-8") as fh:
                fh.readline()
                step = int(fh.readline())
            t = step * float(dt)
            rows.append({"step": step, "t_s": t, "file": str(f.relative_to(self.path)),
                         "hull_x_m": float(hull.get("start_x_m", 0.0)) + float(ship.get("speed_m_s", 0.0)) * t})
        return pd.DataFrame(rows, columns=list(INDEX_COLUMNS)).sort_values("step", ignore_index=True)

    def snapshot(self, step: int | None = None, *, index: int | None = None,
                 all_pieces: bool = False) -> pd.DataFrame:
        """One particle snapshot as a DataFrame (id, x, y, z, radius, vx, vy, vz, submerged_fraction, ca_*, and
        active where the engine writes it: 1 integrated, 0 idle far-field ice).

        run.snapshot(1200) is the snapshot of step 1200; run.snapshot(index=-1) the last one. The frame's
        attrs hold step, t_s and hull_x_m of that snapshot.

        A run with the moving window (speedups.moving_window) writes every piece of the channel with a state
        column: 0 in the scene, 1 held out ahead (where the packing has it, at rest), 2 removed (where it was last
        seen, at rest). The frame holds the pieces in the scene, as brash-post's statistics read them;
        all_pieces=True gives every piece with its state (a picture of the whole channel).
        """
        if (step is None) == (index is None):
            raise TypeError("snapshot(): give a step or index=..., not both and not neither")
        snaps = self.snapshots
        if step is not None:
            rows = snaps[snaps["step"] == step]
            if rows.empty:
                have = ", ".join(str(s) for s in snaps["step"].tolist()[:20]) or "none"
                raise RunError(f"{self.path / INDEX_FILE}: no snapshot at step {step} (steps: {have})")
            row = rows.iloc[0]
        else:
            assert index is not None
            if not -len(snaps) <= index < len(snaps):
                raise RunError(f"{self.path / INDEX_FILE}: snapshot index {index} out of range "
                               f"({len(snaps)} snapshots)")
            row = snaps.iloc[index]
        if (self.path / INDEX_FILE).is_file():
            df = self._read_csv(Path("particles") / str(row["file"]), ("id", "x", "y", "z", "radius"),
                                f"listed in {INDEX_FILE} for step {int(row['step'])}")
        else:
            df = self._read_native_dump(self.path / str(row["file"]))
        if "state" in df.columns:
            bad = sorted(set(df["state"].tolist()) - set(PIECE_STATES))
            if bad:
                raise RunError(f"{self.path / 'particles' / str(row['file'])}: column state: {bad} not among "
                               f"{', '.join(f'{k} ({v})' for k, v in PIECE_STATES.items())}")
            if not all_pieces:
                df = df[df["state"] == 0].reset_index(drop=True)
        df.attrs.update(step=int(row["step"]), t_s=float(row["t_s"]), hull_x_m=float(row["hull_x_m"]))
        return df

    def _read_native_dump(self, file: Path) -> pd.DataFrame:
        """One dump custom file: its columns (radius from diameter where only that is given) plus the submerged
        fraction of each sphere below water.level_m."""
        lines = file.read_text(encoding="utf-8").splitlines()
        head = next((i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")), None)
        if head is None:
            raise RunError(f"{file}: no ITEM: ATOMS line (not a LIGGGHTS dump custom file)")
        names = lines[head].split()[2:]
        df = pd.read_csv(file, sep=r"\s+", skiprows=head + 1, header=None, names=names)
        if "radius" not in df.columns and "diameter" in df.columns:
            df["radius"] = df["diameter"] / 2
        missing = [c for c in ("id", "x", "y", "z", "radius") if c not in df.columns]
        if missing:
            raise RunError(f"{file}: column(s) {', '.join(missing)} missing (ITEM: ATOMS {' '.join(names)})")
        level = float((self.case.get("water") or {}).get("level_m", 0.0))
        r = df["radius"]
        h = (level - (df["z"] - r)).clip(lower=0).clip(upper=2 * r)  # submerged height of the sphere
        df["submerged_fraction"] = h * h * (3 * r - h) / (4 * r ** 3)
        return df

    # ---- brash-post's report -----------------------------------------------------------------------
    @cached_property
    def report(self) -> dict | None:
        """report.json as a dict, or None when brash-post has not run on this directory yet."""
        if not (self.path / REPORT_FILE).is_file():
            return None
        return self._read_json(REPORT_FILE)

    def resistance(self) -> Resistance:
        """Mean resistance and its 95 % CI at model and full scale, from report.json."""
        rep = self.report
        if rep is None:
            raise RunError(f"{self.path / REPORT_FILE} is missing: run `brash-post {self.path}` first")
        file = self.path / REPORT_FILE
        if rep.get("met_no_ice"):
            raise RunError(f"{file}: the hull met no ice in the averaging window {rep.get('window_s')} s: "
                           "no resistance (report.json met_no_ice)")
        model = rep.get("resistance_model_N")
        if not isinstance(model, dict) or model.get("mean") is None or model.get("ci95") is None:
            raise RunError(f"{file}: no resistance_model_N.mean / ci95 (status {rep.get('status')!r}; "
                           f"notes: {'; '.join(rep.get('notes', [])) or 'none'})")
        window = rep.get("window_s")
        if not (isinstance(window, list) and len(window) == 2):
            raise RunError(f"{file}: window_s is not a [start, end] pair: {window!r}")
        fsicr = rep.get("fsicr") or {}
        return Resistance(
            mean_N=float(model["mean"]),
            ci95_N=float(model["ci95"]),
            full_kN=_optional_float(rep.get("resistance_full_kN")),
            full_ci95_kN=_optional_float(rep.get("resistance_full_ci95_kN")),
            window_s=(float(window[0]), float(window[1])),
            plateau_found=(model.get("blocking") or {}).get("plateau_found"),
            fsicr_R_CH_kN=_optional_float(fsicr.get("R_CH_kN")),
            ratio_fsicr_to_sim=_optional_float(rep.get("ratio_fsicr_to_sim")),
            notes=tuple(rep.get("notes", [])),
        )

    def resistance_split(self) -> ResistanceSplit:
        """The resistance of each part of the hull force split over the window, from report.json; RunError saying
        why when the run has none (an engine that does not record it, a run from before the split)."""
        rep = self.report
        if rep is None:
            raise RunError(f"{self.path / REPORT_FILE} is missing: run `brash-post {self.path}` first")
        file = self.path / REPORT_FILE
        split = rep.get("resistance_split_model_N")
        if split is None:
            why = rep.get("resistance_split_not_recorded")
            if rep.get("met_no_ice"):
                why = "the hull met no ice in the averaging window (report.json met_no_ice)"
            raise RunError(f"{file}: no hull force split: {why or 'resistance_split_model_N is null'}")
        if not isinstance(split, dict):
            raise RunError(f"{file}: resistance_split_model_N is not an object: {split!r}")
        scale = rep.get("lambda")
        to_kN = float(scale) ** 3 / 1000.0 if scale is not None else None
        parts = {}
        for name in SPLIT_PARTS:
            p = split.get(name)
            if not isinstance(p, dict) or p.get("mean") is None or p.get("ci95") is None:
                raise RunError(f"{file}: resistance_split_model_N.{name} has no mean / ci95: {p!r}")
            mean, ci95 = float(p["mean"]), float(p["ci95"])
            parts[name] = SplitPart(mean, ci95, None if to_kN is None else mean * to_kN,
                                    None if to_kN is None else ci95 * to_kN, bool(p.get("contact", True)))
        x_par = split.get("x_par_m")
        return ResistanceSplit(parts, (float(x_par[0]), float(x_par[1])) if isinstance(x_par, list) else None)
