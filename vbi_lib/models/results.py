"""What a crossing returns: one family of results whatever the model.

:class:`Crossing` holds what every model computes (time histories, the DAF of each span, the
contact-force checks) and offers the same views, export and plots; each model adds its own
fields in a subclass (the bridge coordinate of the one-coordinate model, the modal
coordinates of the many-mode model).  :class:`BatchResult` is what
:func:`vbi_lib.simulate_many` returns for any model: one row of summaries per crossing.

Displacements are positive up (a deflection under load is negative); the DAF divides the
largest *downward* midspan deflection by the model's static deflection (88)-(91).  Plots and
tables use the display units of :mod:`vbi_lib.display`.

Every crossing also gives the displacement, bending moment and shear at any section
(:meth:`Crossing.displacement_at`, :meth:`Crossing.moment_at`, :meth:`Crossing.shear_at`)
and their extremes, static counterparts and DAFs (:meth:`Crossing.sections`), computed after
the run from the modal coordinates by the mode-acceleration method
(:mod:`vbi_lib.models.sections`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from .. import _validation as check
from .. import display
from ..bridges import Bridge
from ..modes import BeamModes
from ..validity import ContactFlags
from ..vehicles import VehicleSystem, as_system
from .sections import (
    FACES,
    SectionResponse,
    check_method,
    check_side,
    from_first_load,
    governing_faces,
    section_histories,
    section_history,
    snap_to_supports,
    static_counterpart,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["BatchResult", "Crossing"]

_KINDS = ("displacement", "deflection", "contact", "vehicle")


def _spans(n: int) -> str:
    return "1 span" if n == 1 else f"{n} spans"


def _stations(x: object) -> np.ndarray:
    """Stations from the bridge start as a 1-D float array of at least one (range checked
    where the modes are evaluated)."""
    if isinstance(x, str | bytes) or x is None:
        raise TypeError(f"x={x!r} must be stations [m] from the bridge start (numbers)")
    sections = np.atleast_1d(check.real_array("x", x)).ravel()
    if sections.size == 0:
        raise ValueError(f"x={x!r} must give one or more stations [m] from the bridge start")
    return sections


@dataclass(frozen=True, eq=False, kw_only=True)
class Crossing(ContactFlags):
    """One crossing: time histories (SI, displacements positive up) and the DAF of each span.

    Attributes
    ----------
    model
        The model's name (a key of :data:`vbi_lib.models.driver.MODELS`).
    bridge, vehicle
        The inputs (any vehicle of :mod:`vbi_lib.vehicles`).
    speed
        Vehicle speed [m/s].
    bridge_start
        Station of the first support [m].
    time, position
        Time [s] from the start and station of the first axle [m] at every node, shape
        ``(n_time,)`` (the wheel of the study's sprung mass).
    dof_displacement, dof_velocity
        ``(n_time, n_dofs)``: every degree of freedom of the vehicle from its static position
        [m or rad] and its rate, in the order of ``vehicle.system.dof_names``.
    vehicle_displacement, vehicle_velocity
        The first degree of freedom, ``(n_time,)``: ``u_v`` [m] of the study's sprung mass,
        the sprung mass of a quarter car, the bounce of a rigid truck.
    midspan_displacement
        ``(n_time, n_spans)`` [m], what the span DAFs read: ``psi(m_j) z_b`` (one-coordinate
        model), the mode-acceleration displacement (modal model).
    axle_contact_force
        ``(n_time, n_axles)``: force each axle presses on the road [N] (negative: tension of
        a bilateral contact; 0: a tyre in flight).
    contact_force
        Their sum ``(n_time,)`` [N]; for the study's sprung mass ``F_c = m_v g + F``.
    span_of_step
        Per node: 0 while the first axle is off the bridge, else the span of the step from
        the node.
    daf
        Per span, the largest downward deflection of its midspan over the whole run over the
        largest static one under the vehicle's axle loads in every position, by the model's
        own statics (one-shape, one axle ``P / k*`` (88)-(91); exact for the modal model).
    static_deflection
        The largest of those static deflections [m] (:mod:`~vbi_lib.models.statics`).

    dt
        Largest time step used [s].
    coupled, convective
        The options the crossing ran with.
    min_contact_force_ratio
        Smallest contact force of an axle on the bridge over its static load (the worst
        axle): below 0 a bilateral contact would have to pull the road down (the model's
        contact assumption failed); 0 when a tyre flew.
    tension_fraction
        Fraction of the time on the bridge (any axle on it) with a tensile contact force.
    flight_fraction
        Fraction of the time on the bridge with a unilateral tyre off the road (modelled).
    contact_events
        ``(n_events, 4)``: every take-off and landing of a tyre, located inside its step:
        time [s], axle (0-based), +1 take-off or -1 landing, axle station [m]; see
        :meth:`flights`.
    notes
        Sentences on how the crossing was run and where it left the model's validity.
    """

    model: str
    bridge: Bridge
    vehicle: object
    speed: float
    bridge_start: float
    time: np.ndarray
    position: np.ndarray
    dof_displacement: np.ndarray
    dof_velocity: np.ndarray
    vehicle_displacement: np.ndarray
    vehicle_velocity: np.ndarray
    midspan_displacement: np.ndarray
    axle_contact_force: np.ndarray
    contact_force: np.ndarray
    span_of_step: np.ndarray
    daf: np.ndarray
    static_deflection: float
    dt: float
    coupled: bool = True
    convective: bool = True
    min_contact_force_ratio: float = np.nan
    tension_fraction: float = 0.0
    flight_fraction: float = 0.0
    contact_events: np.ndarray = field(default_factory=lambda: np.empty((0, 4)))
    notes: tuple[str, ...] = ()

    # ------------------------------------------------------------------ views
    def flights(self) -> pd.DataFrame:
        """Each flight of a tyre: axle (1-based), take-off and landing time [s] and station
        [m], and duration [s]; NaN landing when the run ended in the air.

        Examples
        --------
        >>> import vbi_lib as vbi
        >>> car = vbi.QuarterCar.from_frequencies(4e3, 500.0, 1.5, 12.0, footprint=0.0)
        >>> road = vbi.Profile.step(40.0, 0.01, position=10.0, height=0.05)
        >>> run = vbi.simulate(vbi.Bridge(10.0, 1, 1e10, 5e3), car, road, 20.0, 25.0)
        >>> len(run.flights()) > 0 and bool((run.flights()["duration [s]"] > 0).all())
        True
        """
        rows = []
        events = self.contact_events
        for axle in np.unique(events[:, 1]).astype(int):
            own = events[events[:, 1] == axle]
            for i in np.flatnonzero(own[:, 2] > 0):
                land = own[i + 1] if i + 1 < len(own) else np.full(4, np.nan)
                rows.append((axle + 1, own[i, 0], land[0], own[i, 3], land[3]))
        table = pd.DataFrame(
            rows,
            columns=["axle", "take-off [s]", "landing [s]", "take-off station [m]",
                     "landing station [m]"],
        )  # fmt: skip
        table["duration [s]"] = table["landing [s]"] - table["take-off [s]"]
        return table

    @property
    def system(self) -> VehicleSystem:
        """The vehicle as a :class:`~vbi_lib.vehicles.VehicleSystem` (its axles and dofs)."""
        return as_system(self.vehicle)

    @property
    def weight(self) -> float:
        """The vehicle's weight, the sum of its static axle loads [N]."""
        return self.system.weight

    @property
    def axle_position(self) -> np.ndarray:
        """Station of every axle [m], shape ``(n_time, n_axles)``."""
        return self.position[:, None] - self.system.offsets[None, :]

    @property
    def axle_on_bridge(self) -> np.ndarray:
        """Whether each axle is on the bridge (ends included), shape ``(n_time, n_axles)``."""
        rel = self.axle_position - self.bridge_start
        return (rel >= -1e-12) & (rel <= self.bridge.length + 1e-12)

    @property
    def on_bridge(self) -> np.ndarray:
        """True at nodes where an axle is on the bridge (ends included), shape ``(n_time,)``."""
        return self.axle_on_bridge.any(axis=1)

    @property
    def contact_force_ratio(self) -> np.ndarray:
        """Total contact force over the vehicle's weight at every node [-]."""
        return self.contact_force / self.weight

    @property
    def axle_contact_force_ratio(self) -> np.ndarray:
        """Each axle's contact force over its static load, ``(n_time, n_axles)`` [-]."""
        return self.axle_contact_force / self.system.static_loads[None, :]

    @property
    def contact_force_amplification(self) -> float:
        """Largest contact force of an axle on the bridge over its static load [-]."""
        return float(self.axle_contact_force_ratio[self.axle_on_bridge].max())

    # ------------------------------------------------------------------ sections
    def modal_history(self) -> tuple[BeamModes, np.ndarray]:
        """The bridge's modes and their coordinates ``(n_time, N)``; supplied by each model."""
        raise NotImplementedError(f"{self.model!r} crossings do not give section responses")

    def _axles(self) -> tuple[np.ndarray, np.ndarray]:
        """Downward axle loads on the bridge [N] and their stations from its start [m].

        Both ``(n_time, n_axles)``; an axle off the bridge carries no load on it.
        """
        offsets = as_system(self.vehicle).offsets
        positions = (self.position - self.bridge_start)[:, None] - offsets[None, :]
        on = (positions >= -1e-12) & (positions <= self.bridge.length + 1e-12)
        return np.where(on, self.axle_contact_force, 0.0), positions

    def _histories(self, function, sections, *args):  # noqa: ANN001, ANN002, ANN202
        modes, q = self.modal_history()
        return from_first_load(function, modes, q, *self._axles(), sections, *args)

    def _section(
        self, x: float | np.ndarray, effect: str, method: str, side: str | tuple[str, ...] = "left"
    ) -> np.ndarray:
        modes, _ = self.modal_history()
        sections = snap_to_supports(modes.supports, _stations(x))
        values = self._histories(section_history, sections, effect, method, side)
        return values[:, 0] if np.ndim(x) == 0 else values

    def displacement_at(
        self, x: float | np.ndarray, method: str = "mode-acceleration"
    ) -> np.ndarray:
        """Displacement history [m] (positive up) at stations ``x`` from the bridge start.

        ``method``: ``"mode-acceleration"`` (default: exact statics plus the modes'
        dynamics) or ``"mode-displacement"`` (the plain modal series
        ``sum_n phi_n(x) q_n(t)``); see :mod:`vbi_lib.models.sections`.

        Returns shape ``(n_time,)`` for one station, ``(n_time, n_x)`` for several.

        Raises
        ------
        ValueError
            A station off the bridge, an unknown method.
        """
        return self._section(x, "displacement", method)

    def moment_at(self, x: float | np.ndarray, method: str = "mode-acceleration") -> np.ndarray:
        """Bending moment history [N m] (sagging positive) at stations ``x`` from the start.

        By the mode-acceleration method by default, which is accurate with a few modes; the
        ``"mode-displacement"`` series ``EI sum_n phi_n''(x) q_n(t)`` converges slowly (terms
        fall as ``1/n^2``).  Shapes and errors as :meth:`displacement_at`.
        """
        return self._section(x, "moment", method)

    def shear_at(
        self, x: float | np.ndarray, method: str = "mode-acceleration", side: str = "left"
    ) -> np.ndarray:
        """Shear history [N] (``V = dM/dx``) at stations ``x`` from the bridge start.

        The shear jumps at an axle and, by the reaction, at a support: ``side`` gives the face,
        ``"left"`` (default) or ``"right"``; at the bridge's ends both give the one on it.
        By the mode-acceleration method by default; the mode-displacement series
        (third derivatives of the modes) does not converge under a concentrated load.
        Shapes and errors as :meth:`displacement_at` (and an unknown ``side``).
        """
        return self._section(x, "shear", method, check_side(side))

    def sections(
        self,
        x: float | np.ndarray,
        method: str = "mode-acceleration",
        side: str | tuple[str, ...] = "governing",
    ) -> SectionResponse:
        """Displacement, moment and shear at sections, their extremes and DAFs.

        Each effect's static counterpart is its extreme when the vehicle's weight crawls
        across (:func:`vbi_lib.beam_statics.static_envelope`), so each section and effect
        has its own DAF, with where and when each extreme occurs.  At an interior support
        the shear jumps by the reaction: by default the result gives the governing face (the
        larger static shear: the design shear) and names it (``faces``, a ``face`` column).

        Parameters
        ----------
        x
            Stations from the bridge start [m].
        method
            ``"mode-acceleration"`` (default) or ``"mode-displacement"``.
        side
            Face of the shear at a support: ``"governing"`` (default), ``"left"`` or
            ``"right"``; or one of ``"left"`` and ``"right"`` for each station (a station
            given twice with both gives both faces).

        Returns
        -------
        SectionResponse

        Raises
        ------
        ValueError
            A station off the bridge, an unknown method or side.
        """
        method = check_method(method)
        modes, _ = self.modal_history()
        sections = snap_to_supports(modes.supports, _stations(x))
        system = as_system(self.vehicle)
        axles = (system.static_loads, system.offsets)
        if isinstance(side, str) and check_side(side, FACES) == "governing":
            faces = governing_faces(modes, sections, *axles, method)
        elif isinstance(side, str):
            faces = (side,) * sections.size
        else:
            faces = tuple(check_side(s) for s in side)
            if len(faces) != sections.size:
                raise ValueError(
                    f"side={side!r} must give one face for each of the {sections.size} stations"
                )
        static = static_counterpart(modes, sections, *axles, method, faces)
        displacement, moment, shear = self._histories(section_histories, sections, method, faces)
        plural = "s" if modes.count > 1 else ""
        notes = [
            f"section responses by the {method} method with {modes.count} mode{plural}; "
            f"extremes at the nodes (steps up to {np.diff(self.position).max():.3g} m)"
        ]
        if self.lost_contact:
            notes += [n for n in self.notes if "contact" in n.lower()]
        return SectionResponse(
            bridge=self.bridge,
            sections=sections,
            time=self.time,
            position=self.position - self.bridge_start,
            displacement=displacement,
            moment=moment,
            shear=shear,
            static=static,
            method=method,
            modes=modes.count,
            lost_contact=self.lost_contact,
            notes=tuple(notes),
        )

    # ------------------------------------------------------------------ export
    def to_dataframe(self) -> pd.DataFrame:
        """The histories as a table, one row per node, in the display units.

        Columns: time, wheel (first axle) position from the bridge start, each span's
        midspan displacement, the vehicle's displacement, the contact force and its ratio to
        the weight; for vehicles with more degrees of freedom or axles, one column per
        further degree of freedom and, per axle, its contact force and ratio to its load.
        """
        columns = {
            display.label("time", "time"): self.time,
            display.label("position from bridge start", "length"): display.value(
                self.position - self.bridge_start, "length"
            ),
        }
        for j in range(self.midspan_displacement.shape[1]):
            columns[display.label(f"midspan displacement, span {j + 1}", "deflection")] = (
                display.value(self.midspan_displacement[:, j], "deflection")
            )
        columns[display.label("vehicle displacement", "deflection")] = display.value(
            self.vehicle_displacement, "deflection"
        )
        system = self.system
        for i in range(1, system.n_dofs):
            name = f"{system.dof_names[i]} displacement"
            if system.dof_units[i] == "rad":
                columns[f"{name} [rad]"] = self.dof_displacement[:, i]
            else:
                columns[display.label(name, "deflection")] = display.value(
                    self.dof_displacement[:, i], "deflection"
                )
        columns[display.label("contact force", "force")] = display.value(
            self.contact_force, "force"
        )
        columns["contact force / weight [-]"] = self.contact_force_ratio
        if system.n_axles > 1:
            ratios = self.axle_contact_force_ratio
            for a in range(system.n_axles):
                columns[display.label(f"axle {a + 1} contact force", "force")] = display.value(
                    self.axle_contact_force[:, a], "force"
                )
                columns[f"axle {a + 1} contact force / load [-]"] = ratios[:, a]
        return pd.DataFrame(columns)

    def plot(
        self, ax: Axes | None = None, kind: str = "displacement", span: int | None = None
    ) -> Axes:
        """Plot a history against the wheel position from the start of the bridge.

        Parameters
        ----------
        ax
            A matplotlib axes; a new figure when ``None``.
        kind
            ``"displacement"``: midspan displacement over the static deflection (a DAF scale);
            ``"deflection"``: midspan displacement in display units; ``"contact"``: contact
            force over the weight (each axle's over its load when there are several), with
            the zero line where contact is lost; ``"vehicle"``: the vehicle's displacements
            (its translational degrees of freedom).
        span
            Only this span (1-based) for the midspan kinds; all spans by default.

        Returns
        -------
        matplotlib.axes.Axes
        """
        import matplotlib.pyplot as plt

        if kind not in _KINDS:
            raise ValueError(f"kind={kind!r} is not known; use one of {', '.join(_KINDS)}")
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        x = display.value(self.position - self.bridge_start, "length")
        if kind in ("displacement", "deflection"):
            spans = range(self.bridge.n_spans) if span is None else [span - 1]
            for j in spans:
                y = self.midspan_displacement[:, j]
                if kind == "displacement":
                    y = y / self.static_deflection
                else:
                    y = display.value(y, "deflection")
                ax.plot(x, y, label=f"span {j + 1}")
            if kind == "displacement":
                ax.set_ylabel("midspan displacement / $w_{static}$ [-]")
            else:
                ax.set_ylabel(display.label("midspan displacement", "deflection"))
            if self.bridge.n_spans > 1:
                ax.legend(loc="best")
        elif kind == "contact":
            system = self.system
            if system.n_axles == 1:
                ax.plot(x, self.contact_force_ratio, color="C3")
            else:
                for a in range(system.n_axles):
                    ax.plot(x, self.axle_contact_force_ratio[:, a], label=f"axle {a + 1}")
                ax.legend(loc="best")
            ax.axhline(0.0, color="k", lw=0.8)
            ax.set_ylabel("$F_c / P$ [-]")
        else:
            system = self.system
            if system.n_dofs == 1:
                ax.plot(x, display.value(self.vehicle_displacement, "deflection"), color="C2")
            else:
                for i, (name, unit) in enumerate(zip(system.dof_names, system.dof_units,
                                                     strict=True)):  # fmt: skip
                    if unit == "m":
                        y = display.value(self.dof_displacement[:, i], "deflection")
                        ax.plot(x, y, label=name)
                ax.legend(loc="best")
            ax.set_ylabel(display.label("vehicle displacement", "deflection"))
        ax.axvspan(0, display.value(self.bridge.length, "length"), color="0.93", zorder=0)
        ax.set_xlabel(display.label("wheel position from the start of the bridge", "length"))
        return ax

    def __repr__(self) -> str:
        dafs = ", ".join(f"{d:.3f}" for d in self.daf)
        text = (
            f"{type(self).__name__}({_spans(self.bridge.n_spans)}, "
            f"{display.fmt(self.speed, 'speed')}: DAF {dafs}"
        )
        if self.outside_validity:
            text += f"; CONTACT LOST (min F_c/P {self.min_contact_force_ratio:.2f})"
        if self.flight_fraction > 0:
            text += f"; tyre off the road {self.flight_fraction:.0%} of the time"
        return text + ")"


@dataclass(frozen=True, eq=False, kw_only=True)
class BatchResult(ContactFlags):
    """Summaries of many crossings (no time histories), one entry per crossing.

    Attributes
    ----------
    model
        The model's name.
    speed
        Vehicle speed of each crossing [m/s], shape ``(n,)``.
    daf
        ``(n, max(2, n_spans))`` DAF of each span (NaN beyond a crossing's spans, e.g. the
        second column for one-span bridges).
    contact_force_amplification
        Largest contact force on the bridge over the weight, ``(n,)``.
    peak_contact_position
        Station of that force [m], ``(n,)``.
    min_contact_force_ratio
        Smallest contact force on the bridge over the static load (worst axle), ``(n,)``;
        below 0 the crossing left the model's validity (the tyre would pull the road down).
    tension_fraction
        Fraction of the time on the bridge with a tensile contact force, ``(n,)``.
    dt
        Largest time step of each crossing [s], ``(n,)``.
    flight_fraction
        Fraction of the time on the bridge with a unilateral tyre off the road, ``(n,)``.
    """

    model: str
    speed: np.ndarray
    daf: np.ndarray
    contact_force_amplification: np.ndarray
    peak_contact_position: np.ndarray
    min_contact_force_ratio: np.ndarray
    tension_fraction: np.ndarray
    dt: np.ndarray
    flight_fraction: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.flight_fraction is None:
            object.__setattr__(self, "flight_fraction", np.zeros_like(self.tension_fraction))

    def __len__(self) -> int:
        return int(self.speed.size)

    def to_dataframe(self) -> pd.DataFrame:
        """One row per crossing: speed (display units), DAFs and the contact checks."""
        return pd.DataFrame(
            {
                display.label("speed", "speed"): display.value(self.speed, "speed"),
                **{f"daf span {j + 1}": self.daf[:, j] for j in range(self.daf.shape[1])},
                "contact force amplification": self.contact_force_amplification,
                "min contact force ratio": self.min_contact_force_ratio,
                "tension fraction": self.tension_fraction,
                "flight fraction": self.flight_fraction,
                "lost contact": self.lost_contact,
                display.label("dt", "time"): self.dt,
            }
        ).rename_axis("crossing")

    def plot(self, ax: Axes | None = None, kind: str = "daf") -> Axes:
        """Plot the DAF (``kind="daf"``) or the contact-force extremes (``"contact"``) by speed.

        Crossings that lost contact are marked with crosses.
        """
        import matplotlib.pyplot as plt

        if kind not in ("daf", "contact"):
            raise ValueError(f"kind={kind!r} is not known; use 'daf' or 'contact'")
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        order = np.argsort(self.speed, kind="stable")
        v = display.value(self.speed[order], "speed")
        lost = self.outside_validity[order]
        flew = self.flight_fraction[order] > 0
        if kind == "daf":
            for j in range(self.daf.shape[1]):
                y = self.daf[order, j]
                if np.isnan(y).all():
                    continue
                ax.plot(v, y, "o-", ms=3, label=f"span {j + 1}")
                ax.plot(v[lost], y[lost], "x", color="k", ms=7)
                ax.plot(v[flew], y[flew], "^", color="0.4", ms=5, mfc="none")
            ax.set_ylabel("DAF [-]")
        else:
            ax.plot(v, self.contact_force_amplification[order], "o-", ms=3, label="largest")
            ax.plot(v, self.min_contact_force_ratio[order], "o-", ms=3, label="smallest")
            ax.axhline(0.0, color="k", lw=0.8)
            ax.set_ylabel("$F_c / P$ [-]")
        if lost.any():
            ax.plot([], [], "x", color="k", label="contact lost (outside validity)")
        if flew.any():
            ax.plot([], [], "^", color="0.4", mfc="none", label="a tyre left the road")
        ax.legend(loc="best")
        ax.set_xlabel(display.label("speed", "speed"))
        return ax

    def __repr__(self) -> str:
        worst = np.nanmax(self.daf) if np.isfinite(self.daf).any() else np.nan
        text = f"BatchResult({len(self)} crossings, {self.model}: largest DAF {worst:.3f}"
        lost = int(self.outside_validity.sum())
        if lost:
            text += f"; CONTACT LOST in {lost}"
        flew = int((self.flight_fraction > 0).sum())
        if flew:
            text += f"; a tyre left the road in {flew}"
        return text + ")"
