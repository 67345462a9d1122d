r"""Vehicles with tyres and several axles, each reduced to a :class:`VehicleSystem`.

* :class:`QuarterCar`: a sprung mass on a suspension, an unsprung (axle) mass and a tyre
  that pushes but never pulls.  Degrees of freedom ``(u_s, u_u)``.
* :class:`IndependentAxles`: several axles at fixed spacings, each carrying its own sprung
  mass (the study's idealisation applied per axle), optionally each on a :class:`Tyre`.
* :class:`RigidTruck`: one rigid body with bounce and pitch on two or more axle groups,
  optionally each on a :class:`Tyre` (then each axle adds an unsprung mass).

An :class:`Axle` gives the station (distance behind the first axle), the static load, the
suspension's spring and damper and, optionally, the tyre.  Without a tyre the suspension is
the contact, bilateral as in the study; with one, the suspension joins the body to the axle
mass and the tyre is the (unilateral) contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .. import _validation as check
from ..ranges import check_range, outside_note, warn_outside
from ..units import g as GRAVITY
from .footprint import DEFAULT_FOOTPRINT
from .sprung_mass import Vehicle
from .system import VehicleSystem

__all__ = ["Axle", "IndependentAxles", "QuarterCar", "RigidTruck", "Tyre"]


def _notes(*checks: tuple[str, float, str]) -> tuple[str, ...]:
    """The sentences of :func:`~vbi_lib.ranges.outside_note` for ``(key, value, name)``s."""
    notes = (outside_note(key, value, name) for key, value, name in checks)
    return tuple(n for n in notes if n)


def _damping_ratio(damping: float, stiffness: float, mass: float) -> float:
    """``c / (2 sqrt(k m))``, the damping ratio of a mass on a spring and a damper."""
    return damping / (2.0 * math.sqrt(stiffness * mass))


@dataclass(frozen=True)
class Tyre:
    """A tyre and the unsprung mass it carries (axle, wheels, brakes).

    Parameters
    ----------
    unsprung_mass
        Mass below the suspension [kg], > 0.
    stiffness
        Vertical tyre stiffness [N/m] (all tyres of the axle together).
    damping
        Tyre damping coefficient [N s/m] (small: the tyre is nearly elastic).
    footprint
        Contact length over which the tyre averages the road [m]
        (:data:`~vbi_lib.vehicles.footprint.DEFAULT_FOOTPRINT`, 0.25 m, by default).
    unilateral
        ``True`` (default): the tyre pushes but never pulls, the wheel may fly.
    """

    unsprung_mass: float
    stiffness: float
    damping: float = 0.0
    footprint: float = DEFAULT_FOOTPRINT
    unilateral: bool = True

    def __post_init__(self) -> None:
        mass = check_range("unsprung_mass", self.unsprung_mass, warn=False)
        object.__setattr__(self, "unsprung_mass", mass)
        object.__setattr__(self, "stiffness", check.positive("tyre stiffness", self.stiffness))
        object.__setattr__(self, "damping", check.non_negative("tyre damping", self.damping))
        object.__setattr__(self, "footprint", check_range("footprint", self.footprint, warn=False))
        object.__setattr__(self, "unilateral", check.flag("unilateral", self.unilateral))
        for note in self.notes:
            warn_outside(note)

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on the unsprung mass and footprint outside their intended ranges (what
        the constructor warns of)."""
        return _notes(("unsprung_mass", self.unsprung_mass, "unsprung_mass"),
                      ("footprint", self.footprint, "footprint"))  # fmt: skip


@dataclass(frozen=True)
class QuarterCar:
    """A quarter car: sprung mass, suspension, unsprung mass and a tyre that can leave the road.

    Degrees of freedom ``(u_s, u_u)``, the sprung and unsprung displacements [m] from the
    static position; the tyre's contact force :math:`F_c = \\max(0, P + k_t (r - u_u) +
    c_t (\\dot r - \\dot u_u))` with :math:`P = (m_s + m_u) g` (see
    :mod:`vbi_lib.vehicles.system`).

    Parameters
    ----------
    sprung_mass, unsprung_mass
        [kg], both > 0.
    suspension_stiffness, suspension_damping
        Between the two masses [N/m], [N s/m].
    tyre_stiffness, tyre_damping
        Between the unsprung mass and the road [N/m], [N s/m].
    footprint
        Tyre contact length [m] (default 0.25 m).
    unilateral
        ``False`` ties the tyre to the road (to compare with the study's assumption).

    Raises
    ------
    TypeError, ValueError
        A value of the wrong type, or a mass, footprint or uncoupled frequency outside its
        range of validity (:data:`vbi_lib.ranges.RANGES`).

    Examples
    --------
    Body bounce 2 Hz on a rigid tyre and axle hop 12 Hz; coupled through the tyre the
    bounce frequency drops:

    >>> car = QuarterCar.from_frequencies(15_000.0, 1_100.0, body_hz=2.0, axle_hop_hz=12.0)
    >>> car.system.frequencies_hz.round(2).tolist()
    [1.57, 12.06]
    """

    sprung_mass: float
    unsprung_mass: float
    suspension_stiffness: float
    suspension_damping: float
    tyre_stiffness: float
    tyre_damping: float = 0.0
    footprint: float = DEFAULT_FOOTPRINT
    unilateral: bool = True

    def __post_init__(self) -> None:
        for name, key in (("sprung_mass", "vehicle_mass"), ("unsprung_mass", "unsprung_mass")):
            object.__setattr__(self, name, check_range(key, getattr(self, name), name, warn=False))
        for name in ("suspension_stiffness", "tyre_stiffness"):
            object.__setattr__(self, name, check.positive(name, getattr(self, name)))
        for name in ("suspension_damping", "tyre_damping"):
            object.__setattr__(self, name, check.non_negative(name, getattr(self, name)))
        object.__setattr__(self, "footprint", check_range("footprint", self.footprint, warn=False))
        object.__setattr__(self, "unilateral", check.flag("unilateral", self.unilateral))
        body = math.sqrt(self.suspension_stiffness / self.sprung_mass) / (2 * math.pi)
        hop = math.sqrt((self.suspension_stiffness + self.tyre_stiffness) / self.unsprung_mass) / (
            2 * math.pi
        )
        for name, value in (("body frequency", body), ("axle hop frequency", hop)):
            check_range("vehicle_frequency", value, f"{name} (from masses and stiffnesses)",
                        warn=False)  # fmt: skip
        for note in self.notes:
            warn_outside(note)

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on the masses, the suspension's and tyre's damping ratios and the
        footprint outside their intended ranges (what the constructor warns of); the
        frequencies are judged by
        :attr:`system`, whose :attr:`~vbi_lib.vehicles.VehicleSystem.notes` hold these and
        its own."""
        zeta = _damping_ratio(self.suspension_damping, self.suspension_stiffness,
                              self.sprung_mass)  # fmt: skip
        zeta_t = _damping_ratio(self.tyre_damping, self.tyre_stiffness, self.unsprung_mass)
        return _notes(
            ("vehicle_mass", self.sprung_mass, "sprung_mass"),
            ("unsprung_mass", self.unsprung_mass, "unsprung_mass"),
            ("vehicle_damping_ratio", zeta, "suspension_damping_ratio"),
            ("vehicle_damping_ratio", zeta_t, "tyre_damping_ratio"),
            ("footprint", self.footprint, "footprint"),
        )

    @classmethod
    def from_frequencies(
        cls,
        sprung_mass: float,
        unsprung_mass: float,
        body_hz: float,
        axle_hop_hz: float,
        suspension_damping_ratio: float = 0.1,
        tyre_damping_ratio: float = 0.0,
        footprint: float = DEFAULT_FOOTPRINT,
        unilateral: bool = True,
    ) -> QuarterCar:
        """A quarter car from its two uncoupled frequencies.

        ``body_hz`` is the sprung mass on its suspension alone,
        :math:`\\sqrt{k_s/m_s}/2\\pi`; ``axle_hop_hz`` the unsprung mass between the
        suspension and the tyre, :math:`\\sqrt{(k_s + k_t)/m_u}/2\\pi`.  The damping
        ratios are of those two oscillators (the suspension's with the sprung mass, the
        tyre's with the unsprung mass), each >= 0: 1 or more is overdamped, accepted and
        warned of (``vehicle_damping_ratio`` in :data:`vbi_lib.ranges.RANGES`).
        """
        m_s = check_range("vehicle_mass", sprung_mass, "sprung_mass", warn=False)
        m_u = check_range("unsprung_mass", unsprung_mass, warn=False)
        w_s = 2.0 * math.pi * check_range("vehicle_frequency", body_hz, "body_hz", warn=False)
        w_u = 2.0 * math.pi * check_range("vehicle_frequency", axle_hop_hz, "axle_hop_hz",
                                          warn=False)  # fmt: skip
        k_s = m_s * w_s**2
        k_t = m_u * w_u**2 - k_s
        if k_t <= 0:
            raise ValueError(
                f"axle_hop_hz={axle_hop_hz!r} is too low for body_hz={body_hz!r} with these "
                f"masses: the tyre stiffness would be {k_t:.3g} N/m; raise axle_hop_hz"
            )
        # any damping ratio >= 0: 1 or more is an overdamped suspension (or tyre), warned of
        # by the quarter car built here, whose notes carry it
        z_s = check_range("vehicle_damping_ratio", suspension_damping_ratio,
                          "suspension_damping_ratio", warn=False)  # fmt: skip
        z_t = check_range("vehicle_damping_ratio", tyre_damping_ratio, "tyre_damping_ratio",
                          warn=False)  # fmt: skip
        return cls(m_s, m_u, k_s, 2 * z_s * m_s * w_s, k_t, 2 * z_t * math.sqrt(k_t * m_u),
                   footprint, unilateral)  # fmt: skip

    @classmethod
    def from_vehicle(
        cls,
        vehicle: Vehicle,
        unsprung_mass: float,
        tyre_stiffness: float,
        tyre_damping: float = 0.0,
        footprint: float = DEFAULT_FOOTPRINT,
        unilateral: bool = True,
    ) -> QuarterCar:
        """The study's sprung mass (body and suspension kept) put on an axle and a tyre.

        The weight grows by the unsprung mass's.
        """
        if not isinstance(vehicle, Vehicle):
            raise TypeError(f"vehicle must be a vbi.Vehicle, got {type(vehicle).__name__}")
        return cls(vehicle.mass, unsprung_mass, vehicle.stiffness, vehicle.damping,
                   tyre_stiffness, tyre_damping, footprint, unilateral)  # fmt: skip

    @property
    def weight(self) -> float:
        """``(m_s + m_u) g`` [N]."""
        return (self.sprung_mass + self.unsprung_mass) * GRAVITY

    @cached_property
    def system(self) -> VehicleSystem:
        """Two degrees of freedom ``(u_s, u_u)`` and one contact, the tyre."""
        k, c = self.suspension_stiffness, self.suspension_damping
        return VehicleSystem(
            mass=np.diag([self.sprung_mass, self.unsprung_mass]),
            stiffness=[[k, -k], [-k, k]],
            damping=[[c, -c], [-c, c]],
            contact=[[0.0, 1.0]],
            offsets=[0.0],
            static_loads=[self.weight],
            contact_stiffness=[self.tyre_stiffness],
            contact_damping=[self.tyre_damping],
            unilateral=[self.unilateral],
            footprint=[self.footprint],
            dof_names=("sprung mass", "unsprung mass"),
            name="quarter car",
            given_notes=self.notes,
        )


@dataclass(frozen=True)
class Axle:
    """One axle (or axle group) of a truck.

    Parameters
    ----------
    offset
        Distance behind the truck's first axle [m] (0 for the first).
    load
        Static axle load [N] (all of it: sprung share and, with a tyre, the axle's own mass).
    stiffness, damping
        The suspension over this axle [N/m], [N s/m].
    tyre
        ``None``: the suspension stands on the road (bilateral, the study's idealisation);
        a :class:`Tyre`: an unsprung mass and a tyre under the suspension.
    """

    offset: float
    load: float
    stiffness: float
    damping: float = 0.0
    tyre: Tyre | None = None

    def __post_init__(self) -> None:
        offset = check_range("axle_offset", self.offset, "offset", warn=False)
        object.__setattr__(self, "offset", offset)
        object.__setattr__(self, "load", check_range("vehicle_weight", self.load, "load",
                                                     warn=False))  # fmt: skip
        object.__setattr__(self, "stiffness", check.positive("stiffness", self.stiffness))
        object.__setattr__(self, "damping", check.non_negative("damping", self.damping))
        if self.tyre is not None and not isinstance(self.tyre, Tyre):
            raise TypeError(f"tyre must be a vbi.vehicles.Tyre or None, got {self.tyre!r}")
        if self.tyre is not None and self.tyre.unsprung_mass * GRAVITY >= self.load:
            raise ValueError(
                f"the tyre's unsprung_mass={self.tyre.unsprung_mass!r} kg weighs more than the "
                f"axle load={self.load!r} N; lower it or raise the load"
            )
        for note in self._own_notes():
            warn_outside(note)

    def _own_notes(self) -> tuple[str, ...]:
        zeta = _damping_ratio(self.damping, self.stiffness, self.sprung_load / GRAVITY)
        return _notes(("axle_offset", self.offset, "offset"), ("vehicle_weight", self.load, "load"),
                      ("vehicle_damping_ratio", zeta, "suspension_damping_ratio"))  # fmt: skip

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on the offset, the load, the suspension's damping ratio and the tyre
        outside their intended ranges (what the constructors of the axle and its tyre warn
        of)."""
        return self._own_notes() + (() if self.tyre is None else self.tyre.notes)

    @property
    def sprung_load(self) -> float:
        """The load the suspension carries [N]: the axle load less the unsprung weight."""
        unsprung = 0.0 if self.tyre is None else self.tyre.unsprung_mass * GRAVITY
        return self.load - unsprung


def _axles(axles: object) -> tuple[Axle, ...]:
    items = tuple(axles) if isinstance(axles, list | tuple) else ()
    if not items or not all(isinstance(a, Axle) for a in items):
        raise TypeError(f"axles must be a non-empty list of vbi.vehicles.Axle, got {axles!r}")
    if len(items) > 20:
        raise ValueError(f"axles has {len(items)} axles; a vehicle has at most 20")
    offsets = [a.offset for a in items]
    if offsets[0] != 0.0 or any(b <= a for a, b in zip(offsets, offsets[1:], strict=False)):
        raise ValueError(
            f"axle offsets {offsets} must start at 0 (the first axle) and increase to the rear"
        )
    return items


def _axle_notes(axles: tuple[Axle, ...]) -> tuple[str, ...]:
    return tuple(f"axle {a + 1}: {note}" for a, axle in enumerate(axles) for note in axle.notes)


class _Assembly:
    """Rows and columns of a system being assembled (suspensions, tyres, contacts)."""

    def __init__(self, n: int, n_axles: int) -> None:
        self.M = np.zeros((n, n))
        self.K = np.zeros((n, n))
        self.C = np.zeros((n, n))
        self.E = np.zeros((n_axles, n))
        self.k = np.zeros(n_axles)
        self.c = np.zeros(n_axles)
        self.unilateral = np.zeros(n_axles, dtype=bool)
        self.footprint = np.zeros(n_axles)

    def spring(self, upper: np.ndarray, lower: int, k: float, c: float) -> None:
        """A suspension between the body motion ``upper @ u`` and the axle dof ``lower``."""
        b = upper.copy()
        b[lower] -= 1.0
        self.K += k * np.outer(b, b)
        self.C += c * np.outer(b, b)

    def contact(self, a: int, row: np.ndarray, axle: Axle) -> None:
        """Contact ``a`` moves with ``row @ u``: the tyre if any, else the suspension."""
        self.E[a] = row
        if axle.tyre is None:
            self.k[a], self.c[a] = axle.stiffness, axle.damping
        else:
            t = axle.tyre
            self.k[a], self.c[a] = t.stiffness, t.damping
            self.unilateral[a], self.footprint[a] = t.unilateral, t.footprint

    def system(self, axles: tuple[Axle, ...], names: list[str], units: list[str],
               name: str) -> VehicleSystem:  # fmt: skip
        return VehicleSystem(
            mass=self.M, stiffness=self.K, damping=self.C, contact=self.E,
            offsets=[a.offset for a in axles], static_loads=[a.load for a in axles],
            contact_stiffness=self.k, contact_damping=self.c, unilateral=self.unilateral,
            footprint=self.footprint, dof_names=tuple(names), dof_units=tuple(units), name=name,
            given_notes=_axle_notes(axles),
        )  # fmt: skip


@dataclass(frozen=True)
class IndependentAxles:
    """Several axles, each carrying its own sprung mass of ``sprung_load / g``.

    Without tyres this is the study's sprung mass repeated per axle; it is the superposition
    of one-axle trucks when the road and the bridge stay linear (bilateral contact).

    Examples
    --------
    >>> from vbi_lib import units as u
    >>> t = IndependentAxles([Axle(0.0, 100e3, 4e6, 2e4), Axle(4.0, 150e3, 6e6, 3e4)])
    >>> t.system.n_dofs, round(t.weight / 1e3), t.system.wheelbase
    (2, 250, 4.0)
    """

    axles: tuple[Axle, ...]
    name: str = "independent axles"

    def __post_init__(self) -> None:
        object.__setattr__(self, "axles", _axles(self.axles))

    @property
    def weight(self) -> float:
        """Sum of the axle loads [N]."""
        return float(sum(a.load for a in self.axles))

    @property
    def notes(self) -> tuple[str, ...]:
        """Each axle's :attr:`Axle.notes`, prefixed with its number."""
        return _axle_notes(self.axles)

    @cached_property
    def system(self) -> VehicleSystem:
        """Per axle a sprung mass ``u_s`` (and an unsprung mass ``u_u`` with a tyre)."""
        sizes = [1 if a.tyre is None else 2 for a in self.axles]
        asm = _Assembly(sum(sizes), len(self.axles))
        names, units, i = [], [], 0
        for a, (axle, size) in enumerate(zip(self.axles, sizes, strict=True)):
            asm.M[i, i] = axle.sprung_load / GRAVITY
            names.append(f"axle {a + 1} sprung mass")
            row = np.zeros(sum(sizes))
            row[i] = 1.0
            if size == 2:
                asm.M[i + 1, i + 1] = axle.tyre.unsprung_mass
                asm.spring(row, i + 1, axle.stiffness, axle.damping)
                names.append(f"axle {a + 1} unsprung mass")
                row = np.zeros(sum(sizes))
                row[i + 1] = 1.0
            asm.contact(a, row, axle)
            units += ["m"] * size
            i += size
        return asm.system(self.axles, names, units, self.name)


@dataclass(frozen=True)
class RigidTruck:
    """A rigid body with bounce and pitch on two or more axle groups.

    The body's mass is the sprung loads over g; its centre of mass is where their moment
    balances (so the given axle loads are its static reactions).  Degrees of freedom: the
    bounce ``z`` of the centre of mass [m], the pitch ``theta`` [rad] (nose up positive),
    then one unsprung mass per axle that has a tyre.  Axle ``a`` at distance ``xi_a`` ahead
    of the centre of mass moves the body at ``z + xi_a theta``.

    Parameters
    ----------
    axles
        At least two :class:`Axle`.
    pitch_inertia
        Body's moment of inertia about the transverse axis through its centre of mass
        [kg m^2].

    Examples
    --------
    >>> t = RigidTruck([Axle(0.0, 60e3, 3e5), Axle(5.0, 140e3, 7e5)], pitch_inertia=1.2e5)
    >>> round(t.centre_of_mass, 3)   # metres behind the first axle: 5 * 140 / 200
    3.5
    """

    axles: tuple[Axle, ...]
    pitch_inertia: float
    name: str = "rigid truck"

    def __post_init__(self) -> None:
        object.__setattr__(self, "axles", _axles(self.axles))
        if len(self.axles) < 2:
            raise ValueError(
                f"a rigid truck pitches on at least two axle groups; got {len(self.axles)} "
                "(use QuarterCar or Vehicle for one)"
            )
        object.__setattr__(
            self, "pitch_inertia", check.positive("pitch_inertia", self.pitch_inertia)
        )

    @property
    def weight(self) -> float:
        """Sum of the axle loads [N]."""
        return float(sum(a.load for a in self.axles))

    @property
    def notes(self) -> tuple[str, ...]:
        """Each axle's :attr:`Axle.notes`, prefixed with its number."""
        return _axle_notes(self.axles)

    @property
    def body_mass(self) -> float:
        """Sprung (body) mass [kg]."""
        return sum(a.sprung_load for a in self.axles) / GRAVITY

    @property
    def centre_of_mass(self) -> float:
        """Distance of the body's centre of mass behind the first axle [m]."""
        loads = np.array([a.sprung_load for a in self.axles])
        return float(loads @ [a.offset for a in self.axles] / loads.sum())

    @cached_property
    def system(self) -> VehicleSystem:
        """Bounce, pitch and the unsprung masses; contacts at each axle."""
        with_tyre = [a for a, axle in enumerate(self.axles) if axle.tyre is not None]
        n = 2 + len(with_tyre)
        asm = _Assembly(n, len(self.axles))
        asm.M[0, 0] = self.body_mass
        asm.M[1, 1] = self.pitch_inertia
        names, units = ["bounce", "pitch"], ["m", "rad"]
        for a, axle in enumerate(self.axles):
            body = np.zeros(n)
            body[0] = 1.0
            body[1] = self.centre_of_mass - axle.offset
            if axle.tyre is None:
                asm.contact(a, body, axle)
                continue
            i = 2 + with_tyre.index(a)
            asm.M[i, i] = axle.tyre.unsprung_mass
            asm.spring(body, i, axle.stiffness, axle.damping)
            names.append(f"axle {a + 1} unsprung mass")
            units.append("m")
            row = np.zeros(n)
            row[i] = 1.0
            asm.contact(a, row, axle)
        return asm.system(self.axles, names, units, self.name)
