"""Design trucks and several trucks at once: :func:`hs20` and :class:`Convoy`."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Literal

from .. import _validation as check
from ..ranges import check_range
from ..units import ft, g, kip
from .footprint import DEFAULT_FOOTPRINT
from .system import VehicleSystem, as_system, stack
from .trucks import Axle, IndependentAxles, RigidTruck, Tyre

__all__ = ["HS20_AXLE_LOADS", "Convoy", "hs20"]

#: AASHTO HS20 design truck: axle loads front to rear [N] (8, 32 and 32 kip).
HS20_AXLE_LOADS = (8 * kip, 32 * kip, 32 * kip)
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
        Distance from the second to the third axle [m], 14 to 30 ft.
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
    spacing = check.positive("rear_spacing", rear_spacing)
    if not (14 * ft - 1e-9 <= spacing <= 30 * ft + 1e-9):
        raise ValueError(
            f"rear_spacing={rear_spacing!r} m is outside AASHTO's 14 to 30 ft "
            f"({14 * ft:.4f} to {30 * ft:.4f} m)"
        )
    check.choice("body", body, ("independent", "rigid"))
    tyres = check.flag("tyres", tyres)
    omega = 2.0 * math.pi * check_range("vehicle_frequency", bounce_hz, "bounce_hz", warn=False)
    # any ratio >= 0: 1 or more is an overdamped suspension (warned of, not refused); the
    # axles and tyres warn of a damping ratio or footprint outside the intended range
    zeta = check_range("vehicle_damping_ratio", suspension_damping_ratio,
                       "suspension_damping_ratio", warn=False)  # fmt: skip
    check_range("footprint", footprint, warn=False)
    axles = []
    for i, (offset, load) in enumerate(zip((0.0, 14 * ft, 14 * ft + spacing), HS20_AXLE_LOADS,
                                           strict=True)):  # fmt: skip
        tyre = None
        if tyres:
            count = 2 if i == 0 else 4
            tyre = Tyre(700.0 if i == 0 else 1100.0, count * TYRE_STIFFNESS,
                        count * TYRE_DAMPING, footprint)  # fmt: skip
        sprung = (load - (0.0 if tyre is None else tyre.unsprung_mass * g)) / g
        axles.append(Axle(offset, load, sprung * omega**2, 2 * zeta * sprung * omega, tyre))
    name = f"HS20 ({spacing / ft:g} ft rear spacing, {body}{', tyres' if tyres else ''})"
    if body == "independent":
        return IndependentAxles(tuple(axles), name=name)
    sprung_mass = sum(a.sprung_load for a in axles) / g
    inertia = sprung_mass * axles[-1].offset ** 2 / 12.0
    return RigidTruck(tuple(axles), pitch_inertia=inertia, name=name)
