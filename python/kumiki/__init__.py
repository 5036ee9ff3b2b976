"""Kumiki from Python: the models of four papers on self-assembling modular robots, run by the same
Rust core as the page and the ``kumiki`` command, so a scenario and seed give the same state hash
in all three.

    import kumiki
    s = kumiki.open("amas-L")                 # a preset, lesson, file, share link, JSON text or dict
    rows = s.run(seeds=10)                     # one row per seed: a pandas DataFrame
    trace = s.trace(["built", "collisions"])   # per-step metrics of one run
    e = kumiki.experiment("amas-fig23")        # a built-in experiment, a file, a link or a dict
    df = e.run()                               # its rows; df.attrs["provenance"] as in its CSV
    e.summary(df)                              # statistics per condition and comparisons
    e.svg(df, 0); e.pdf(df, 0)                 # its figures

See python/README.md for everything the package does.
"""

from __future__ import annotations

import datetime as _dt
import json as _json
import os as _os
from typing import Any, Iterable, Mapping, Optional, Sequence, Union

import pandas as _pd

from . import _kumiki

__all__ = [
    "Scenario",
    "Experiment",
    "open",
    "experiment",
    "check",
    "presets",
    "experiments",
    "lessons",
    "metrics",
    "format_number",
    "__version__",
    "COMMIT",
]

__version__, COMMIT = _kumiki.version()

_Source = Union[str, _os.PathLike, Mapping[str, Any]]

_ROW_FIELDS = ["scenario", "seed", "completed", "steps", "hash", "scenario_hash", "version"]


def _text(source: _Source) -> str:
    if isinstance(source, Mapping):
        return _json.dumps(source)
    return _os.fspath(source)


def _frame(rows: Sequence[Mapping[str, Any]]) -> _pd.DataFrame:
    """Rows as a DataFrame with the CSV export's columns: the row's fields, then ``params.*`` and
    ``metrics.*`` in sorted order (without the CSV's units; ``attrs["units"]`` has them)."""
    params = sorted({k for r in rows for k in r.get("params", {})})
    names = sorted({k for r in rows for k in r.get("metrics", {})})
    records = []
    for r in rows:
        rec = {f: r.get(f) for f in _ROW_FIELDS}
        rec.update({f"params.{k}": r.get("params", {}).get(k) for k in params})
        rec.update({f"metrics.{k}": r.get("metrics", {}).get(k) for k in names})
        records.append(rec)
    columns = _ROW_FIELDS + [f"params.{k}" for k in params] + [f"metrics.{k}" for k in names]
    df = _pd.DataFrame.from_records(records, columns=columns)
    units = {"steps": "steps"}
    table = {m["name"]: m["unit"] for m in metrics_table()}
    units.update({f"metrics.{k}": table[k] for k in names if k in table})
    df.attrs["units"] = units
    df.attrs["rows"] = [dict(r) for r in rows]
    return df


def _rows_of(df: _pd.DataFrame) -> list:
    """The rows behind a DataFrame this package made, in its order (a filtered or sorted frame
    keeps the rows it still holds)."""
    rows = df.attrs.get("rows")
    if rows is None or len(rows) < len(df):
        raise ValueError("this DataFrame was not made by kumiki (its attrs['rows'] is missing)")
    return [rows[i] for i in df.index]


class Scenario:
    """A scenario, read and checked by the core. ``json`` is the scenario as a dict."""

    def __init__(self, source: _Source, allow_large: bool = False):
        text, note = _kumiki.open_scenario(_text(source), allow_large)
        self.json: dict = _json.loads(text)
        self.note: Optional[str] = note
        self.allow_large = allow_large

    @property
    def name(self) -> str:
        return self.json["name"]

    @property
    def model(self) -> str:
        return self.json["model"]

    def __repr__(self) -> str:
        return f"<kumiki.Scenario {self.name!r} ({self.model})>"

    def _text(self) -> str:
        return _json.dumps(self.json)

    def with_(self, **overrides: Any) -> "Scenario":
        """A copy with keys set (``with_(robots=3)``); dotted paths go through ``set=`` of
        :meth:`run`."""
        doc = dict(self.json)
        doc.update(overrides)
        return Scenario(doc, self.allow_large)

    def link(self, base: str = "http://localhost:8080/") -> str:
        """A share link that opens this scenario in the page (and in ``kumiki run``)."""
        return f"{base}#{_kumiki.share_link(self._text())}"

    def run(
        self,
        seeds: Union[int, Iterable[int], None] = None,
        set: Optional[Mapping[str, Any]] = None,
        max_steps: Optional[int] = None,
        jobs: Optional[int] = None,
    ) -> _pd.DataFrame:
        """Runs it: ``seeds`` a count N (seeds 1 to N, as ``kumiki run --seeds N``), a list of
        seeds, or None for the scenario's own. ``set`` overrides fields by dotted path, as
        ``--set``. One row per run, as ``kumiki run`` prints them (a scenario that compares two
        runs gives both rows)."""
        if seeds is None:
            seeds = [self.json["seed"]]
        elif isinstance(seeds, int):
            seeds = list(range(1, seeds + 1))
        sets = [(k, _json.dumps(v)) for k, v in (set or {}).items()]
        rows = _kumiki.run_rows(self._text(), list(seeds), sets, max_steps, jobs, self.allow_large)
        return _frame([_json.loads(r) for r in rows])

    def trace(
        self,
        metrics: Union[str, Sequence[str], None] = None,
        seed: Optional[int] = None,
        every: int = 1,
    ) -> _pd.DataFrame:
        """One run's metrics at every ``every``-th step and at its end: a ``step`` column and one
        column per metric (every metric of the model when ``metrics`` is None)."""
        if isinstance(metrics, str):
            metrics = [metrics]
        t = _json.loads(
            _kumiki.trace(self._text(), seed, list(metrics or []), every, self.allow_large)
        )
        df = _pd.DataFrame({"step": t["step"], **t["values"]})
        df.attrs["scenario"] = self.name
        return df

    def agents(self, seed: Optional[int] = None, every: int = 1) -> _pd.DataFrame:
        """The model's agents (robots on their modules; none for models without them) at every
        ``every``-th step: step, agent, cell, x, y, z, kind and kind_name."""
        records = _json.loads(_kumiki.agents(self._text(), seed, every, self.allow_large))
        columns = ["step", "agent", "cell", "x", "y", "z", "kind", "kind_name"]
        return _pd.DataFrame.from_records(records, columns=columns)


def open(source: _Source, allow_large: bool = False) -> Scenario:  # noqa: A001 - kumiki.open
    """A scenario from a preset or lesson name, a JSON file, a share link, JSON text or a dict."""
    return Scenario(source, allow_large)


def _now() -> str:
    """Now, or the time SOURCE_DATE_EPOCH gives (as ``kumiki sweep`` takes it), in RFC 3339."""
    epoch = _os.environ.get("SOURCE_DATE_EPOCH")
    t = (
        _dt.datetime.fromtimestamp(int(epoch), _dt.timezone.utc)
        if epoch and epoch.strip().isdigit()
        else _dt.datetime.now(_dt.timezone.utc)
    )
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


class Experiment:
    """An experiment: scenarios × a grid (lists or ranges) × samples × seeds, read and checked by
    the core."""

    def __init__(self, source: _Source, allow_large: bool = False):
        text = _text(source)
        definition, self.runs = _kumiki.open_experiment(text, allow_large)
        self.json: dict = _json.loads(definition)
        self._source = definition
        self.allow_large = allow_large

    @property
    def name(self) -> str:
        return self.json["name"]

    def __repr__(self) -> str:
        return f"<kumiki.Experiment {self.name!r}: {self.runs} runs>"

    def run(self, jobs: Optional[int] = None) -> _pd.DataFrame:
        """Every run, in job order, one row each: the same rows as ``kumiki sweep``.
        ``attrs["provenance"]`` is the provenance its CSV and JSON exports carry (program,
        commit, models' behaviour versions, seeds, time, the experiment as read)."""
        provenance, rows = _kumiki.sweep(self._source, _now(), jobs, self.allow_large)
        df = _frame([_json.loads(r) for r in rows])
        df.attrs["provenance"] = _json.loads(provenance)
        return df

    def _rows(self, df: _pd.DataFrame) -> str:
        return _json.dumps(_rows_of(df))

    def summary(self, df: _pd.DataFrame) -> list:
        """The summary plots' statistics, as ``kumiki sweep --summary`` prints them: per
        condition and value, then (three or more conditions) each Kruskal-Wallis test, then each
        pair compared, first minus second, with Holm's p. A frame with fewer rows than the runs
        gives a last record saying ``partial``."""
        return [_json.loads(x) for x in _kumiki.summary(self._source, self._rows(df))]

    def figures(self, df: _pd.DataFrame) -> list:
        """Each figure's record (what is drawn, as the page's table reads it)."""
        return [_json.loads(f) for f, _ in _kumiki.figures(self._source, self._rows(df))]

    def svg(self, df: _pd.DataFrame, index: int = 0) -> str:
        """Figure ``index`` as SVG, as the page and ``kumiki sweep --plot svg`` draw it."""
        return _kumiki.figures(self._source, self._rows(df))[index][1]

    def pdf(self, df: _pd.DataFrame, index: int = 0) -> bytes:
        """Figure ``index`` as a one-page PDF (``kumiki sweep --plot pdf``)."""
        return _kumiki.figure_pdf(self._source, self._rows(df), index)

    def export(self, df: _pd.DataFrame, format: str = "csv", time: Optional[str] = None) -> str:
        """The rows exported as the page and ``kumiki sweep`` write them: ``csv``, ``json`` or
        ``traces``, with their provenance (``time`` defaults to the frame's)."""
        when = time or df.attrs.get("provenance", {}).get("time") or _now()
        return _kumiki.export_rows(self._source, self._rows(df), format, when)


def experiment(source: _Source, allow_large: bool = False) -> Experiment:
    """An experiment from a built-in name, a JSON file, an experiment link (``#x1.…``), JSON
    text or a dict."""
    return Experiment(source, allow_large)


def check(handins: Iterable[_Source], exercise: Optional[_Source] = None) -> _pd.DataFrame:
    """Hand-ins (links, files or scenarios) graded by replaying them, as ``kumiki check``: one row
    each with met, because, completed, steps, hash, the locked fields edited and (with the
    teacher's ``exercise``) every field changed, or the error."""
    graded = _kumiki.check([_text(h) for h in handins], None if exercise is None else _text(exercise))
    columns = ["name", "met", "because", "completed", "steps", "hash", "locked_edited", "changed",
               "exercise_edited", "goal_metrics", "error"]
    records = []
    for i, g in enumerate(graded, start=1):
        g = _json.loads(g)
        records.append({"handin": i, **{c: g.get(c) for c in columns}})
    return _pd.DataFrame.from_records(records)


def presets() -> list:
    """The built-in scenarios' names."""
    return _kumiki.names("presets")


def experiments() -> list:
    """The built-in experiments' names."""
    return _kumiki.names("experiments")


def lessons() -> list:
    """The built-in lessons' names."""
    return _kumiki.names("lessons")


def metrics_table(model: Optional[str] = None) -> list:
    return _json.loads(_kumiki.metrics(model))


def metrics(model: Optional[str] = None) -> _pd.DataFrame:
    """Every metric (of one model or all): model, name, unit and what it measures."""
    return _pd.DataFrame.from_records(metrics_table(model))


def format_number(value: float) -> str:
    """A number as every figure and table shows it (the core's one rounding rule)."""
    return _kumiki.format_number(float(value))


