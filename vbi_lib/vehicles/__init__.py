"""Vehicles: the study's sprung mass, the quarter car, multi-axle trucks and convoys.

Every vehicle reduces to one :class:`VehicleSystem` (a linear mechanical system with contact
points, :mod:`~vbi_lib.vehicles.system`), which both crossing models integrate; a vehicle
type is data, not a kernel.

* :class:`Vehicle`: the study's sprung mass (46)-(47), (85); one bilateral contact.
* :class:`QuarterCar`: sprung and unsprung masses, a tyre that can leave the road.
* :class:`Axle`, :class:`Tyre`, :class:`IndependentAxles`, :class:`RigidTruck`: several
  axles as independent sprung masses or as one body with bounce and pitch.
* :class:`Convoy`: several vehicles at fixed headways; :func:`hs20`, :func:`hl93_truck`,
  :func:`hl93_tandem`: AASHTO's design truck and tandem; :func:`permit_vehicle`: any axles;
  :func:`governing_rear_spacing`: the design truck's rear spacing that governs a section.
* :func:`seen_by_tyre`: the road averaged over a tyre's footprint (:mod:`.footprint`).
"""

from .fleet import (
    HL93_TANDEM_AXLE_LOADS,
    HS20_AXLE_LOADS,
    Convoy,
    RearSpacingSearch,
    governing_rear_spacing,
    hl93_tandem,
    hl93_truck,
    hs20,
    permit_vehicle,
)
from .footprint import DEFAULT_FOOTPRINT, footprint_average, seen_by_tyre
from .sprung_mass import Vehicle
from .system import VehicleSystem, as_system, stack
from .trucks import Axle, IndependentAxles, QuarterCar, RigidTruck, Tyre

__all__ = [
    "DEFAULT_FOOTPRINT",
    "HL93_TANDEM_AXLE_LOADS",
    "HS20_AXLE_LOADS",
    "Axle",
    "Convoy",
    "IndependentAxles",
    "QuarterCar",
    "RearSpacingSearch",
    "RigidTruck",
    "Tyre",
    "Vehicle",
    "VehicleSystem",
    "as_system",
    "footprint_average",
    "governing_rear_spacing",
    "hl93_tandem",
    "hl93_truck",
    "hs20",
    "permit_vehicle",
    "seen_by_tyre",
    "stack",
]
