"""Design trucks, permit vehicles and several vehicles at once.

* :func:`hs20` and :func:`hl93_truck`: AASHTO's design truck (8, 32 and 32 kip; 14 ft, then
  14 to 30 ft), :func:`hl93_tandem`: the design tandem (two 25 kip axles 4 ft apart)
  (AASHTO LRFD Bridge Design Specifications, 3.6.1.2.2 and 3.6.1.2.3);
* :func:`permit_vehicle`: any list of axle loads and spacings (a permit or a measured truck);
* :func:`governing_rear_spacing`: the rear axle spacing of the design truck, 14 to 30 ft,
  that gives the largest static effect at each section (LRFD 3.6.1.2.2: "the spacing
  between the two 32.0 kip axles shall be varied between 14.0 and 30.0 ft to produce
  extreme force effects");
* :class:`Convoy`: several vehicles at fixed headways.

Every vehicle here is built the same way from its axles (:func:`permit_vehicle` with the
design loads): the dynamic parameters are not part of the design loads, and the defaults are
typical of a loaded heavy truck (see :func:`hs20`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Literal

import numpy as np
import pandas as pd

from .. import _validation as check
from ..ranges import check_range
from ..units import ft, g, kip
from .footprint import DEFAULT_FOOTPRINT
from .system import VehicleSystem, as_system, stack
from .trucks import Axle, IndependentAxles, RigidTruck, Tyre

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "HL93_TANDEM_AXLE_LOADS",
    "HS20_AXLE_LOADS",
    "Convoy",
    "RearSpacingSearch",
    "governing_rear_spacing",
    "hl93_tandem",
    "hl93_truck",
    "hs20",
    "permit_vehicle",
]

#: AASHTO HS20 design truck (and LRFD's design truck): axle loads front to rear [N].
HS20_AXLE_LOADS = (8 * kip, 32 * kip, 32 * kip)
#: Distance from the front axle to the second of the design truck [m] (14 ft).
HS20_FRONT_SPACING = 14 * ft
#: The range of the design truck's rear axle spacing [m] (14 to 30 ft).
REAR_SPACING_RANGE = (14 * ft, 30 * ft)
#: AASHTO LRFD design tandem (3.6.1.2.3): two 25 kip axles [N], 4 ft apart.
HL93_TANDEM_AXLE_LOADS = (25 * kip, 25 * kip)
HL93_TANDEM_SPACING = 4 * ft
#: Unsprung mass of a steer axle and of any other axle [kg], and the largest share of an
#: axle's load it may take (light axles of a permit vehicle).
STEER_UNSPRUNG_MASS, AXLE_UNSPRUNG_MASS, UNSPRUNG_SHARE = 700.0, 1100.0, 0.15
#: Tyre stiffness of one heavy-vehicle tyre [N/m] and its damping [N s/m].
TYRE_STIFFNESS = 0.875e6
TYRE_DAMPING = 1.0e3


@dataclass(frozen=True)
class Convoy:
    """Several vehicles following one another in the same lane at fixed headways.

    Parameters
    ----------
    vehicles
        The vehicles, the leading one first (any vehicle of the library).
    headways
        Distance from the first axle of each vehicle to the first axle of the one behind it
        [m], one fewer than ``vehicles``; each must exceed the wheelbase of the vehicle ahead.

    Examples
    --------
    >>> from vbi_lib.vehicles import Vehicle
    >>> car = Vehicle(1e4, 4e6, 2e4)
    >>> pair = Convoy([car, car], [30.0])
    >>> pair.system.offsets.tolist(), pair.system.n_dofs
    ([0.0, 30.0], 2)
    """

    vehicles: tuple
    headways: tuple[float, ...]

    def __post_init__(self) -> None:
        vehicles = tuple(self.vehicles) if isinstance(self.vehicles, list | tuple) else ()
        if len(vehicles) < 1:
            raise ValueError(f"vehicles={self.vehicles!r} must be a list of one or more vehicles")
        systems = [as_system(v) for v in vehicles]
        if isinstance(self.headways, str | bytes) or not hasattr(self.headways, "__len__"):
            raise TypeError(f"headways={self.headways!r} must be a list of distances in metres")
        headways = tuple(
            check_range("headway", h, f"headways[{i}]") for i, h in enumerate(self.headways)
        )
        if len(headways) != len(vehicles) - 1:
            raise ValueError(
                f"headways={list(headways)} needs one distance per following vehicle "
                f"({len(vehicles) - 1})"
            )
        for i, (h, ahead) in enumerate(zip(headways, systems, strict=False)):
            if not (math.isfinite(h) and h > ahead.wheelbase):
                raise ValueError(
                    f"headways[{i}]={h!r} m must exceed the wheelbase of vehicle {i + 1} "
                    f"({ahead.wheelbase:g} m): the vehicles would overlap"
                )
        object.__setattr__(self, "vehicles", vehicles)
        object.__setattr__(self, "headways", headways)

    @property
    def weight(self) -> float:
        """Total weight [N]."""
        return self.system.weight

    @property
    def notes(self) -> tuple[str, ...]:
        """Each vehicle's notes (:attr:`~vbi_lib.vehicles.VehicleSystem.notes`), prefixed
        with its place in the convoy."""
        return self.system.given_notes

    @cached_property
    def system(self) -> VehicleSystem:
        """All the vehicles as one block-diagonal system."""
        positions = [0.0]
        for h in self.headways:
            positions.append(positions[-1] + h)
        return stack([as_system(v) for v in self.vehicles], positions,
                     name=f"convoy of {len(self.vehicles)}")  # fmt: skip


def _dynamics(bounce_hz: float, suspension_damping_ratio: float, footprint: float):  # noqa: ANN202
    omega = 2.0 * math.pi * check_range("vehicle_frequency", bounce_hz, "bounce_hz", warn=False)
    # any ratio >= 0: 1 or more is an overdamped suspension (warned of, not refused); the
    # axles and tyres warn of a damping ratio or footprint outside the intended range
    zeta = check_range("vehicle_damping_ratio", suspension_damping_ratio,
                       "suspension_damping_ratio", warn=False)  # fmt: skip
    check_range("footprint", footprint, warn=False)
    return omega, zeta


def _build(
    loads: Sequence[float],
    offsets: Sequence[float],
    name: str,
    *,
    body: str,
    tyres: bool,
    bounce_hz: float,
    suspension_damping_ratio: float,
    footprint: float,
    steer: bool,
    detail: str = "",
) -> IndependentAxles | RigidTruck:
    """A vehicle of axles ``loads`` [N] at ``offsets`` [m] behind the first (module doc),
    named ``"name (detail, body, tyres)"``."""
    check.choice("body", body, ("independent", "rigid"))
    tyres = check.flag("tyres", tyres)
    omega, zeta = _dynamics(bounce_hz, suspension_damping_ratio, footprint)
    axles = []
    for i, (offset, load) in enumerate(zip(offsets, loads, strict=True)):
        tyre = None
        if tyres:
            front = steer and i == 0
            count = 2 if front else 4
            unsprung = STEER_UNSPRUNG_MASS if front else AXLE_UNSPRUNG_MASS
            unsprung = min(unsprung, UNSPRUNG_SHARE * load / g)
            tyre = Tyre(unsprung, count * TYRE_STIFFNESS, count * TYRE_DAMPING, footprint)
        sprung = (load - (0.0 if tyre is None else tyre.unsprung_mass * g)) / g
        axles.append(Axle(offset, load, sprung * omega**2, 2 * zeta * sprung * omega, tyre))
    name = f"{name} ({detail + ', ' if detail else ''}{body}{', tyres' if tyres else ''})"
    if body == "independent" or len(axles) == 1:
        return IndependentAxles(tuple(axles), name=name)
    sprung_mass = sum(a.sprung_load for a in axles) / g
    inertia = sprung_mass * axles[-1].offset ** 2 / 12.0
    return RigidTruck(tuple(axles), pitch_inertia=inertia, name=name)


def _rear_spacing(rear_spacing: object, name: str = "rear_spacing") -> float:
    spacing = check.positive(name, rear_spacing)
    low, high = REAR_SPACING_RANGE
    if not (low - 1e-9 <= spacing <= high + 1e-9):
        raise ValueError(
            f"{name}={rear_spacing!r} m is outside AASHTO's 14 to 30 ft ({low:.4f} to {high:.4f} m)"
        )
    return spacing


def hs20(
    rear_spacing: float = 14 * ft,
    *,
    body: Literal["independent", "rigid"] = "independent",
    tyres: bool = True,
    bounce_hz: float = 3.0,
    suspension_damping_ratio: float = 0.10,
    footprint: float = DEFAULT_FOOTPRINT,
) -> IndependentAxles | RigidTruck:
    """The AASHTO HS20 design truck: 8, 32 and 32 kip axles, 14 ft then 14 to 30 ft apart.

    Axle loads and spacings are AASHTO's (LRFD Bridge Design Specifications, 3.6.1.2.2; the
    HS20-44 truck of the Standard Specifications).  The dynamic parameters are not part of
    the design truck; the defaults are typical of a loaded heavy truck:

    * each axle's sprung load bounces on its suspension at ``bounce_hz`` (3 Hz; heavy-vehicle
      body bounce lies between about 1.5 and 4 Hz, Cebon 1999, *Handbook of Vehicle-Road
      Interaction*) with ``suspension_damping_ratio`` (10 %, the study's truck damping);
    * with ``tyres=True``: an unsprung mass of 700 kg on the steer axle and 1100 kg on each
      of the others, tyres of 0.875 MN/m and 1 kN s/m each, two on the steer axle and four
      (duals) on the others.  The axle-hop frequencies that follow, about 10 and 14 Hz,
      lie in the 8 to 15 Hz range Cebon gives; every tyre averages the road over
      ``footprint`` and can leave it.

    Parameters
    ----------
    rear_spacing
        Distance from the second to the third axle [m], 14 to 30 ft
        (:func:`governing_rear_spacing` finds the one that governs a section).
    body
        ``"independent"``: each axle carries its own sprung mass (:class:`IndependentAxles`);
        ``"rigid"``: one rigid body with bounce and pitch (:class:`RigidTruck`), its pitch
        inertia that of its mass spread evenly over the wheelbase, ``m L^2 / 12``.
    tyres
        Put each axle on an unsprung mass and unilateral tyres.
    bounce_hz, suspension_damping_ratio, footprint
        As above.

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> truck = hs20(rear_spacing=30 * u.ft)
    >>> [round(a.load / u.kip) for a in truck.axles], round(truck.system.wheelbase / u.ft)
    ([8, 32, 32], 44)
    """
    spacing = _rear_spacing(rear_spacing)
    offsets = (0.0, HS20_FRONT_SPACING, HS20_FRONT_SPACING + spacing)
    return _build(HS20_AXLE_LOADS, offsets, "HS20", body=body, tyres=tyres,
                  bounce_hz=bounce_hz, suspension_damping_ratio=suspension_damping_ratio,
                  footprint=footprint, steer=True,
                  detail=f"{spacing / ft:g} ft rear spacing")  # fmt: skip


def hl93_truck(
    rear_spacing: float = 14 * ft,
    *,
    body: Literal["independent", "rigid"] = "independent",
    tyres: bool = True,
    bounce_hz: float = 3.0,
    suspension_damping_ratio: float = 0.10,
    footprint: float = DEFAULT_FOOTPRINT,
) -> IndependentAxles | RigidTruck:
    """The AASHTO LRFD design truck of the HL-93 live load (3.6.1.2.2).

    8, 32 and 32 kip axles, 14 ft and then 14 to 30 ft apart: the axles of the HS20 truck
    (:func:`hs20`, whose dynamic defaults it shares).  HL-93 adds a design lane load of
    0.64 kip/ft, to which LRFD applies no dynamic load allowance (3.6.2.1): it is not a
    vehicle and is not modelled here.

    >>> from vbi_lib import units as u
    >>> truck = hl93_truck()
    >>> truck.name
    'HL-93 design truck (14 ft rear spacing, independent, tyres)'
    >>> [round(a.offset / u.ft, 6) for a in truck.axles]
    [0.0, 14.0, 28.0]
    """
    spacing = _rear_spacing(rear_spacing)
    offsets = (0.0, HS20_FRONT_SPACING, HS20_FRONT_SPACING + spacing)
    return _build(HS20_AXLE_LOADS, offsets, "HL-93 design truck", body=body, tyres=tyres,
                  bounce_hz=bounce_hz, suspension_damping_ratio=suspension_damping_ratio,
                  footprint=footprint, steer=True,
                  detail=f"{spacing / ft:g} ft rear spacing")  # fmt: skip


def hl93_tandem(
    *,
    body: Literal["independent", "rigid"] = "independent",
    tyres: bool = True,
    bounce_hz: float = 3.0,
    suspension_damping_ratio: float = 0.10,
    footprint: float = DEFAULT_FOOTPRINT,
) -> IndependentAxles | RigidTruck:
    """The AASHTO LRFD design tandem of the HL-93 live load (3.6.1.2.3): two 25 kip axles
    4 ft apart.

    A load model, not a vehicle: each axle is given the dynamics of a drive axle of
    :func:`hs20` (its sprung load bouncing at ``bounce_hz``; with ``tyres``, 1100 kg
    unsprung on four tyres).

    >>> from vbi_lib import units as u
    >>> tandem = hl93_tandem()
    >>> [round(a.load / u.kip) for a in tandem.axles], round(tandem.axles[1].offset / u.ft, 6)
    ([25, 25], 4.0)
    """
    return _build(HL93_TANDEM_AXLE_LOADS, (0.0, HL93_TANDEM_SPACING), "HL-93 design tandem",
                  body=body, tyres=tyres, bounce_hz=bounce_hz,
                  suspension_damping_ratio=suspension_damping_ratio, footprint=footprint,
                  steer=False)  # fmt: skip


def permit_vehicle(
    axle_loads: Sequence[float],
    axle_spacings: Sequence[float],
    *,
    body: Literal["independent", "rigid"] = "independent",
    tyres: bool = True,
    bounce_hz: float = 3.0,
    suspension_damping_ratio: float = 0.10,
    footprint: float = DEFAULT_FOOTPRINT,
    name: str = "permit vehicle",
) -> IndependentAxles | RigidTruck:
    """A vehicle of any axles: loads front to rear and the spacing between each pair.

    For a permit load, a measured truck, or two design trucks in a row.  The dynamics are
    those of :func:`hs20`: the first axle is a steer axle (two tyres, 700 kg unsprung),
    every other axle has four tyres and 1100 kg unsprung, the unsprung mass never more than
    15 % of the axle's load.

    Parameters
    ----------
    axle_loads
        Static load of each axle [N], front first; 1 to 20 axles.
    axle_spacings
        Distance from each axle to the next [m], one fewer than the loads, each > 0.
    body, tyres, bounce_hz, suspension_damping_ratio, footprint
        As :func:`hs20`.
    name
        The vehicle's name in results.

    Raises
    ------
    TypeError, ValueError
        Loads or spacings that are not lists of numbers, of the wrong count, outside their
        ranges (:data:`vbi_lib.ranges.RANGES`: ``vehicle_weight`` for a load, ``axle_offset``
        for the distance from the first axle), or a spacing of zero.

    Examples
    --------
    A five-axle permit truck: 12 kip steer, two 34 kip tandems.

    >>> from vbi_lib import units as u
    >>> truck = permit_vehicle([12 * u.kip, 34 * u.kip, 34 * u.kip, 34 * u.kip, 34 * u.kip],
    ...                        [14 * u.ft, 4 * u.ft, 30 * u.ft, 4 * u.ft])
    >>> round(truck.weight / u.kip), round(truck.system.wheelbase / u.ft)
    (148, 52)
    """
    loads = _numbers("axle_loads", axle_loads, 1, 20)
    spacings = _numbers("axle_spacings", axle_spacings, len(loads) - 1, len(loads) - 1)
    for i, spacing in enumerate(spacings):
        if not (math.isfinite(spacing) and spacing > 0):
            raise ValueError(
                f"axle_spacings[{i}]={spacing!r} must be a distance > 0 [m] from axle {i + 1} "
                f"to axle {i + 2}"
            )
    offsets = [0.0]
    for spacing in spacings:
        offsets.append(offsets[-1] + spacing)
    if not isinstance(name, str) or not name.strip():
        raise TypeError(f"name={name!r} must be text")
    return _build(loads, offsets, name.strip(), body=body, tyres=tyres, bounce_hz=bounce_hz,
                  suspension_damping_ratio=suspension_damping_ratio, footprint=footprint,
                  steer=len(loads) > 1)  # fmt: skip


def _numbers(name: str, values: object, low: int, high: int) -> list[float]:
    if isinstance(values, str | bytes) or not hasattr(values, "__len__"):
        raise TypeError(f"{name}={values!r} must be a list of numbers")
    items = [check.number(f"{name}[{i}]", v) for i, v in enumerate(values)]
    if not low <= len(items) <= high:
        count = f"{low}" if low == high else f"{low} to {high}"
        raise ValueError(f"{name}={list(values)!r} must hold {count} values, got {len(items)}")
    return items


# ---------------------------------------------------------------------------- rear spacing
@dataclass(frozen=True, eq=False)
class RearSpacingSearch:
    """The design truck's rear axle spacing that governs each section and effect.

    Attributes
    ----------
    sections
        Stations from the bridge start [m], ``(n_s,)``.
    spacings
        The spacings tried [m], ``(n_k,)``, every 0.5 ft over the range searched.
    extreme
        ``(n_k, 3, n_s)``: the static extreme of each effect (in order
        :data:`vbi_lib.beam_influence.EFFECTS`) that is the larger in size, over both faces of
        a support and the directions asked, with its sign [m up, N m, N].
    governing
        ``(3, n_s)``: the spacing [m] whose extreme is the largest in size (the shortest of
        those within 1e-9 of it).
    """

    sections: np.ndarray
    spacings: np.ndarray
    extreme: np.ndarray
    governing: np.ndarray

    @property
    def value(self) -> np.ndarray:
        """``(3, n_s)``: the static extreme at the governing spacing, signed."""
        k = np.abs(self.spacings[:, None, None] - self.governing[None]).argmin(axis=0)
        return np.take_along_axis(self.extreme, k[None], axis=0)[0]

    def to_dataframe(self) -> pd.DataFrame:
        """One row per section and effect: the governing spacing [ft and m] and its extreme."""
        from ..beam_statics import EFFECTS

        rows = []
        for e, effect in enumerate(EFFECTS):
            for i, x in enumerate(self.sections):
                rows.append({"section [m]": x, "effect": effect,
                             "governing rear spacing [ft]": self.governing[e, i] / ft,
                             "governing rear spacing [m]": self.governing[e, i],
                             "static extreme [SI]": self.value[e, i]})  # fmt: skip
        return pd.DataFrame(rows)

    def plot(self, ax: Axes | None = None, effect: str = "moment") -> Axes:
        """The static extreme of ``effect`` at each section against the rear spacing [ft],
        each over its largest (so the governing spacing is where a line reaches 1)."""
        import matplotlib.pyplot as plt

        from ..beam_statics import effect_index

        e = effect_index(effect)
        if ax is None:
            _, ax = plt.subplots(figsize=(7, 3.2))
        for i, x in enumerate(self.sections):
            size = np.abs(self.extreme[:, e, i])
            if size.max() > 0:
                ax.plot(self.spacings / ft, size / size.max(), label=f"{x:.1f} m")
        ax.set_xlabel("rear axle spacing [ft]")
        ax.set_ylabel(f"static {effect} / largest [-]")
        ax.legend(loc="best", fontsize="small", title="section")
        return ax


def governing_rear_spacing(
    spans: Sequence[float],
    EI: float,
    sections: Sequence[float],
    low: float = REAR_SPACING_RANGE[0],
    high: float = REAR_SPACING_RANGE[1],
    *,
    direction: str = "both",
    side: str | Sequence[str] = "both",
) -> RearSpacingSearch:
    """The rear axle spacing of the design truck that gives the largest static effect.

    AASHTO LRFD 3.6.1.2.2: the spacing of the two 32 kip axles "shall be varied between
    14.0 and 30.0 ft to produce extreme force effects".  The static envelope of the axles
    (:func:`vbi_lib.beam_statics.static_envelope`, exact) is computed every 0.5 ft from
    ``low`` to ``high``; at each section and effect the spacing whose extreme (the larger
    in size of the maximum and the minimum, over both faces of a support) is the largest
    governs.  Positive moments and shears near midspan are governed by 14 ft; negative
    moments over interior supports often by a longer spacing.

    Parameters
    ----------
    spans, EI
        The continuous beam: span lengths [m], flexural rigidity [N m^2].
    sections
        Stations from the bridge start [m].
    low, high
        The range searched [m], within 14 to 30 ft.
    direction
        ``"forward"``, ``"backward"`` or ``"both"`` (default): the directions the truck may
        cross in.
    side
        Face of the shear at a support: ``"both"`` (default: the larger), ``"left"`` or
        ``"right"``, one for all sections or one each.

    Returns
    -------
    RearSpacingSearch

    Examples
    --------
    Over the interior support of two 40 ft spans the negative moment is largest with the
    32 kip axles far apart, one in each span; at midspan 14 ft governs.

    >>> from vbi_lib import units as u
    >>> found = governing_rear_spacing([40 * u.ft, 40 * u.ft], 1e10, [20 * u.ft, 40 * u.ft])
    >>> (found.governing[1] / u.ft).round(1).tolist()
    [14.0, 30.0]
    """
    from ..beam_statics import EFFECTS, SIDES, static_envelope

    low, high = _rear_spacing(low, "low"), _rear_spacing(high, "high")
    if high < low:
        raise ValueError(f"high={high!r} m must not be below low={low!r} m")
    count = max(1, int(round((high - low) / (0.5 * ft)))) + 1
    spacings = np.linspace(low, high, count)
    x = np.atleast_1d(np.asarray(sections, dtype=float))
    sides = [side] * x.size if isinstance(side, str) else list(side)
    if len(sides) != x.size or any(s not in ("both", *SIDES) for s in sides):
        raise ValueError(
            f"side={side!r} must be 'both', 'left' or 'right', or one of them per section"
        )
    extreme = np.empty((count, len(EFFECTS), x.size))
    for k, spacing in enumerate(spacings):
        offsets = (0.0, HS20_FRONT_SPACING, HS20_FRONT_SPACING + spacing)
        best = np.zeros((len(EFFECTS), x.size))
        for face in SIDES:
            take = np.array([s in ("both", face) for s in sides])
            if not take.any():
                continue
            env = static_envelope(spans, EI, x[take], HS20_AXLE_LOADS, offsets, side=face,
                                  direction=direction)  # fmt: skip
            for values in (env.maximum, env.minimum):
                part = best[:, take]
                best[:, take] = np.where(np.abs(values) > np.abs(part), values, part)
        extreme[k] = best
    size = np.abs(extreme)
    top = size.max(axis=0)
    first = np.argmax(size >= top[None] * (1 - 1e-9), axis=0)
    return RearSpacingSearch(x, spacings, extreme, spacings[first])
