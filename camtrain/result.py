"""The result of a run: columns on named axes, grouped in components, scalar metrics, events,
warnings, timings and the plan.

Pure data: no printing; files only through :meth:`Result.save` / :meth:`Result.load`. The report
layer, sweeps and tests read it.

* An **axis** is a column holding the abscissa of other columns: ``cam_angle`` for a valve
  train, ``angle`` for a bearing load diagram; a dynamics run may add ``time``. Every column
  knows its axis.
* A **component** is a named part of the run: the ``closing`` pair of a desmodromic train,
  ``bearing_3`` of a camshaft, later a cylinder's intake train or a ring. A column or metric of a
  component has its own short name (``load``) and a flat name in tables (``closing_load``);
  the train itself is component None.
* An **event** is something that happens at an angle (loss of contact, zero entrainment, a
  handover between the cams of a desmodromic train), with its axis and component.
"""
from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

#: metrics the short repr shows first, when the run has them
_REPR_METRICS = ("max_valve_lift", "load_max", "hertz_max", "film_min", "power_loss_mean",
                 "bounce_speed", "drive_power_mean", "bearings_power_total", "max_eccentricity",
                 "min_film", "power_mean")


def flat_name(name: str, component: str | None) -> str:
    """The name of a component's column or metric in flat tables (cycle.csv, summary.json)."""
    return name if component is None else f"{component}_{name}"


_FLOAT = np.dtype(float)
_ndarray = np.ndarray
_new, _set = object.__new__, object.__setattr__


def _built(cls, fields: dict):
    """An instance of the frozen dataclass ``cls`` with these (complete, checked) fields,
    without the field-by-field frozen ``__init__``: a run adds some 70 columns and metrics,
    and their construction was a measurable share of a short run."""
    obj = _new(cls)
    _set(obj, "__dict__", fields)
    return obj


@dataclass(frozen=True)
class Column:
    """One per-angle (or per-time) quantity on the grid of its axis."""

    values: np.ndarray
    unit: str
    description: str
    axis: str = ""
    name: str = ""
    component: str | None = None


@dataclass(frozen=True)
class Metric:
    """One scalar result; ``angle`` [rad] says where on the cycle it occurs, when it does."""

    value: float
    unit: str
    description: str
    angle: float | None = None
    name: str = ""
    component: str | None = None


@dataclass(frozen=True)
class Event:
    """Something that happens at one abscissa of an axis (``at``, in the axis' unit, SI)."""

    kind: str
    at: float
    description: str
    axis: str = "cam_angle"
    component: str | None = None


@dataclass
class Component:
    """The columns and metrics of one component, by their short names."""

    name: str | None
    columns: dict[str, Column]
    metrics: dict[str, Metric]

    def __getitem__(self, name: str) -> np.ndarray:
        return self.columns[name].values


@dataclass
class Result:
    """Everything a run produced. ``columns`` and ``metrics`` are keyed by flat name."""

    columns: dict[str, Column] = field(default_factory=dict)
    metrics: dict[str, Metric] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    plan: object = None
    events: list[Event] = field(default_factory=list)
    axes: list[str] = field(default_factory=list)
    #: warning -> the finding it states (Result.warn's ``finding``), for the runner to drop a
    #: finding an effect that runs later owns (EffectSpec.supersedes); not saved
    finding_of: dict[str, str] = field(default_factory=dict, repr=False, compare=False)

    # ------------------------------------------------------------------ building

    def add_axis(self, name: str, values, unit: str, description: str) -> None:
        """An abscissa column; the first axis is the default axis of later columns."""
        if name not in self.axes:
            self.axes.append(name)
        self.columns[name] = Column(np.asarray(values, dtype=float), unit, description, name,
                                    name, None)

    def add_column(self, name: str, values, unit: str, description: str, *,
                   component: str | None = None, axis: str | None = None) -> None:
        """A column on ``axis`` (default: the first axis; a result without one makes this
        column its axis)."""
        axes = self.axes
        if axis is None:
            if not axes:
                return self.add_axis(name, values, unit, description)
            axis = axes[0]
        elif axis not in axes:
            raise KeyError(f"no axis {axis!r} in this result (axes: {axes})")
        if type(values) is not _ndarray or values.dtype is not _FLOAT:
            values = np.asarray(values, dtype=float)
        column = _new(Column)   # as _built, inlined: this runs some 40 times a run
        _set(column, "__dict__", {"values": values, "unit": unit, "description": description,
                                  "axis": axis, "name": name, "component": component})
        self.columns[name if component is None else f"{component}_{name}"] = column

    def add_columns(self, columns, component: str | None = None) -> None:
        """Several columns on the first axis, each ``(name, values, unit, description)``: what
        :meth:`add_column` does, in one loop (an effect adds tens of columns per run)."""
        axis = self.axes[0] if self.axes else None
        into = self.columns
        for name, values, unit, description in columns:
            if axis is None:
                self.add_column(name, values, unit, description, component=component)
                axis = self.axes[0]
                continue
            if type(values) is not _ndarray or values.dtype is not _FLOAT:
                values = np.asarray(values, dtype=float)
            column = _new(Column)
            _set(column, "__dict__", {"values": values, "unit": unit,
                                      "description": description, "axis": axis, "name": name,
                                      "component": component})
            into[name if component is None else f"{component}_{name}"] = column

    def add_metrics(self, metrics, component: str | None = None) -> None:
        """Several metrics, each ``(name, value, unit, description[, angle])``, as
        :meth:`add_metric` adds one."""
        into = self.metrics
        for name, value, unit, description, *angle in metrics:
            at = angle[0] if angle else None
            metric = _new(Metric)
            _set(metric, "__dict__", {"value": float(value), "unit": unit,
                                      "description": description,
                                      "angle": None if at is None else float(at),
                                      "name": name, "component": component})
            into[name if component is None else f"{component}_{name}"] = metric

    def add_metric(self, name: str, value: float, unit: str, description: str,
                   angle: float | None = None, *, component: str | None = None) -> None:
        metric = _new(Metric)
        _set(metric, "__dict__", {"value": float(value), "unit": unit,
                                  "description": description,
                                  "angle": None if angle is None else float(angle),
                                  "name": name, "component": component})
        self.metrics[name if component is None else f"{component}_{name}"] = metric

    def add_event(self, kind: str, at: float, description: str, *,
                  component: str | None = None, axis: str | None = None) -> None:
        self.events.append(Event(kind, float(at), description,
                                 axis or (self.axes[0] if self.axes else "cam_angle"), component))

    def warn(self, message: str, finding: str | None = None) -> None:
        """A warning; ``finding`` names what it finds (an event kind, e.g. "zero_entrainment")
        when an effect that runs later may own that finding (EffectSpec.supersedes)."""
        if message not in self.warnings:
            self.warnings.append(message)
        if finding is not None:
            self.finding_of[message] = finding

    def drop_findings(self, kinds: tuple[str, ...]) -> None:
        """Remove the events of these kinds and the warnings stating them (an effect that owns
        the finding is about to run and states its own)."""
        self.events = [e for e in self.events if e.kind not in kinds]
        gone = {w for w, kind in self.finding_of.items() if kind in kinds}
        self.warnings = [w for w in self.warnings if w not in gone]
        self.finding_of = {w: k for w, k in self.finding_of.items() if w not in gone}

    # ------------------------------------------------------------------ reading

    def __getitem__(self, name: str) -> np.ndarray:
        """Column values by flat name, e.g. ``result['lift']``, ``result['closing_load']``."""
        return self.columns[name].values

    @property
    def components(self) -> list[str]:
        """Names of the components, in the order they first appear (the train itself: None,
        not listed)."""
        seen: dict[str, None] = {}
        for item in list(self.columns.values()) + list(self.metrics.values()):
            if item.component is not None:
                seen.setdefault(item.component, None)
        return list(seen)

    def component(self, name: str | None) -> Component:
        """The columns and metrics of one component (None: the train itself), by short name."""
        cols = {c.name or k: c for k, c in self.columns.items() if c.component == name}
        mets = {m.name or k: m for k, m in self.metrics.items() if m.component == name}
        if name is not None and not cols and not mets:
            raise KeyError(f"no component {name!r} (components: {self.components})")
        return Component(name, cols, mets)

    def on_axis(self, axis: str) -> dict[str, Column]:
        """The columns on one axis (the axis itself included), by flat name."""
        return {k: c for k, c in self.columns.items() if (c.axis or self._default_axis) == axis}

    def events_of(self, kind: str) -> list[Event]:
        return [e for e in self.events if e.kind == kind]

    @property
    def _default_axis(self) -> str:
        return self.axes[0] if self.axes else ""

    def to_dataframe(self, axis: str | None = None, units: str = "deck"):
        """The columns on ``axis`` (default: the first) as a pandas DataFrame indexed by the
        axis; column names are flat names, units in ``df.attrs['units']``.

        ``units="deck"`` (default): what cycle.csv and the terminal show, the cam angle in
        degrees, films in µm, stresses in MPa; ``units="si"``: as computed (m, rad, Pa). Needs
        pandas (``pip install 'camtrain[pandas]'``)."""
        pd = _pandas("Result.to_dataframe")
        axis = axis or self._default_axis
        cols = self.on_axis(axis)
        if axis not in cols:
            raise KeyError(f"no axis {axis!r} in this result (axes: {self.axes})")
        shown = {k: _in_units(k, c.unit, units) for k, c in cols.items()}
        index = pd.Index(cols[axis].values * shown[axis][1], name=axis)
        df = pd.DataFrame({k: c.values * shown[k][1] for k, c in cols.items() if k != axis},
                          index=index)
        df.attrs["units"] = {k: unit for k, (unit, _) in shown.items()}
        return df

    def metrics_frame(self, units: str = "deck"):
        """The metrics as a pandas DataFrame indexed by flat name: value and unit (deck units
        by default, as summary.json; ``units="si"``), the angle where each occurs (deg, or rad
        in SI), its component and description."""
        pd = _pandas("Result.metrics_frame")
        rows = {}
        for key, m in self.metrics.items():
            unit, factor = _in_units(key, m.unit, units)
            _, to_angle = _in_units("cam_angle", "rad", units)
            rows[key] = {"value": m.value * factor, "unit": unit,
                         "angle": None if m.angle is None else m.angle * to_angle,
                         "component": m.component, "description": m.description}
        frame = pd.DataFrame.from_dict(rows, orient="index",
                                       columns=["value", "unit", "angle", "component",
                                                "description"])
        frame.index.name = "metric"
        return frame

    def __repr__(self) -> str:
        plan = ", ".join(self.plan.chosen) if self.plan is not None else "none"
        grids = ", ".join(f"{a}[{self.columns[a].values.size}]" for a in self.axes
                          if a in self.columns) or "no axis"
        keys = [k for k in _REPR_METRICS if k in self.metrics] or list(self.metrics)[:6]
        shown = [(k, self.metrics[k]) for k in keys[:6]]
        mets = ", ".join(f"{k}={m.value:.4g} {m.unit}" for k, m in shown)
        more = f", ... ({len(self.metrics)} metrics)" if len(self.metrics) > len(shown) else ""
        comps = f"; components {', '.join(self.components)}" if self.components else ""
        return (f"Result(plan: {plan}; {len(self.columns)} columns on {grids}{comps}; "
                f"metrics: {mets}{more}; {len(self.events)} events; "
                f"{len(self.warnings)} warnings)")

    # ------------------------------------------------------------------ files

    def save(self, path: str | Path) -> Path:
        """Write the result to one ``.npz`` file (arrays, and the rest as JSON inside)."""
        path = Path(path)
        meta = {
            "format": "camtrain.result/1",
            "axes": self.axes,
            "columns": [{"key": k, "unit": c.unit, "description": c.description,
                         "axis": c.axis, "name": c.name, "component": c.component}
                        for k, c in self.columns.items()],
            "metrics": {k: asdict(m) for k, m in self.metrics.items()},
            "events": [asdict(e) for e in self.events],
            "warnings": self.warnings,
            "timings": self.timings,
            "plan": self.plan.as_dict() if self.plan is not None else None,
            "kind": getattr(self.plan, "kind", None),
        }
        arrays = {f"c{i}": c.values for i, c in enumerate(self.columns.values())}
        with path.open("wb") as fh:
            np.savez_compressed(fh, __meta__=np.array(json.dumps(meta)), **arrays)
        return path

    @classmethod
    def load(cls, path: str | Path) -> Result:
        """Read a result written by :meth:`save` (its plan comes back without effect specs)."""
        from camtrain.plan import Plan, Step

        with np.load(Path(path), allow_pickle=False) as z:
            meta = json.loads(str(z["__meta__"]))
            arrays = [z[f"c{i}"] for i in range(len(meta["columns"]))]
        res = cls(axes=list(meta["axes"]), warnings=list(meta["warnings"]),
                  timings=dict(meta["timings"]))
        for c, values in zip(meta["columns"], arrays, strict=True):
            res.columns[c["key"]] = Column(values, c["unit"], c["description"], c["axis"],
                                           c["name"], c["component"])
        res.metrics = {k: Metric(**m) for k, m in meta["metrics"].items()}
        res.events = [Event(**e) for e in meta["events"]]
        if meta["plan"] is not None:
            p = meta["plan"]
            res.plan = Plan(p["mode"], tuple(Step(s["effect"], s["chosen"], s["reason"],
                                                  model=s.get("model", ""))
                                             for s in p["steps"]), meta["kind"] or "valve_train")
        return res


def _pandas(what: str):
    try:
        import pandas as pd
    except ImportError:  # pragma: no cover - depends on the installation
        raise ImportError(f"{what} needs pandas: pip install 'camtrain[pandas]'") from None
    return pd


def _in_units(name: str, si_unit: str, units: str) -> tuple[str, float]:
    """(unit, factor from SI) of a column or metric in "deck" or "si" units: the same rules as
    the files a run writes (one table of display rules, :mod:`camtrain.display_units`)."""
    from camtrain.display_units import output_unit

    return output_unit(name, si_unit, units)
