r"""The one form every vehicle takes in the crossing models: a linear system with contact points.

A vehicle has ``n`` degrees of freedom :math:`u` (vertical translations [m] and pitch
rotations [rad], measured from its static equilibrium on a level road) and ``n_axles``
contact points, the axles, at fixed distances behind the first one.  Its equations are

.. math::
    M \ddot u + C \dot u + K u = E^T (\mathbf{F}_c - \mathbf{P}), \qquad
    \tilde F_a = P_a + k_a (r_a - e_a \cdot u) + c_a (\dot r_a - e_a \cdot \dot u)

with :math:`M` the mass matrix (symmetric positive definite; diagonal for point masses, not
for a pitching body), :math:`K, C` the internal (suspension) stiffness and damping, row
:math:`e_a` of :math:`E` the combination of the degrees of freedom that moves contact point
``a``, :math:`P_a` the static load of axle ``a`` and :math:`k_a, c_a` its contact spring and
damper, acting between :math:`e_a \cdot u` and the road :math:`r_a` under the axle (the
profile seen through the tyre's footprint plus the bridge's deflection there).  The contact
force :math:`F_{c,a}` pressing on the road (the book's notation) is

* **bilateral** (the study's assumption, 46-47): :math:`F_{c,a} = \tilde F_a`, which may
  become tensile;
  the contact spring of the study's sprung mass is its suspension;
* **unilateral** (a tyre): :math:`F_{c,a} = \max(0, \tilde F_a)`; the wheel flies while
  :math:`\tilde F_a`
  would be tensile and lands when it turns compressive again.

Gravity does not appear because :math:`u` is measured from the static equilibrium: the static
loads balance the weight of the masses (checked: a rigid vertical translation :math:`d` with
:math:`E d = 1`, :math:`K d = C d = 0` exists and :math:`E^T \mathbf{P} - g M d` is a set of
suspension preloads :math:`K u_0`).  In flight the released preloads and the weight act
together, so the whole vehicle's centre of mass falls at :math:`g`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from .. import _validation as check
from .. import display
from ..ranges import check_range, outside_note, warn_outside
from ..units import g as GRAVITY

__all__ = ["VehicleSystem", "as_system", "stack"]


def _numbers(name: str, value: Any, ndmin: int) -> np.ndarray:
    """``value`` as a float array; text, bools and objects raise ``TypeError`` naming ``name``."""
    try:
        raw = np.array(value, ndmin=ndmin)
    except (TypeError, ValueError):
        raise ValueError(f"{name}={value!r} must be a rectangular array of numbers") from None
    if raw.dtype.kind not in "iuf":
        check.finite_array(name, raw.ravel())  # raises TypeError naming the first bad entry
    return raw.astype(float)


def _matrix(name: str, value: Any, shape: tuple[int, int]) -> np.ndarray:
    array = _numbers(name, value, 2)
    if array.shape != shape:
        raise ValueError(f"{name} must have shape {shape}; got {array.shape}")
    if not np.isfinite(array).all():
        raise ValueError(f"{name} must hold finite numbers; got {array.tolist()}")
    return array


def _vector(name: str, value: Any, size: int, dtype: type = float) -> np.ndarray:
    if dtype is bool:
        array = np.array(value, ndmin=1)
        if array.dtype != bool:
            raise TypeError(f"{name}={value!r} must be True or False for each axle (bools)")
    else:
        array = _numbers(name, value, 1)
    if array.shape != (size,):
        raise ValueError(f"{name} must have one entry per axle ({size}); got shape {array.shape}")
    if dtype is float and not np.isfinite(array).all():
        raise ValueError(f"{name}={array.tolist()} must hold finite numbers")
    return array


def _symmetric(name: str, array: np.ndarray, definite: bool) -> None:
    scale = max(float(np.abs(array).max()), 1e-300)
    if np.abs(array - array.T).max() > 1e-12 * scale:
        raise ValueError(f"{name} must be symmetric; got {array.tolist()}")
    lowest = float(np.linalg.eigvalsh(array).min()) if array.size else 0.0
    if definite and lowest <= 1e-12 * scale:
        raise ValueError(f"{name} must be positive definite (every mass > 0); got {array.tolist()}")
    if not definite and lowest < -1e-9 * scale:
        raise ValueError(f"{name} must be positive semi-definite; got {array.tolist()}")


@dataclass(frozen=True, eq=False)
class VehicleSystem:
    """A vehicle as a linear mechanical system with contact points (see the module docstring).

    Parameters
    ----------
    mass, stiffness, damping
        ``M`` [kg or kg m^2], ``K`` [N/m ...], ``C`` [N s/m ...], shape ``(n, n)``.
    contact
        ``E``, shape ``(n_axles, n)``: row ``a`` gives the contact point's displacement.
    offsets
        Distance of each axle behind the first axle [m], shape ``(n_axles,)``; the smallest
        is 0 (the vehicle's position is that of its first axle).
    static_loads
        ``W_a`` [N], each > 0; together they carry the vehicle's weight.
    contact_stiffness, contact_damping
        ``k_a`` [N/m] > 0 and ``c_a`` [N s/m] >= 0 of each contact (tyre or, for the study's
        sprung mass, suspension).
    unilateral
        Per axle: ``True`` for a tyre that can leave the road.
    footprint
        Per axle, the tyre's contact length [m] over which it averages the road (0: a point).
    dof_names, dof_units
        Names of the degrees of freedom and their units (``"m"`` or ``"rad"``).
    name
        A label.
    given_notes
        Sentences on the parameters of the vehicle this system stands for that lie outside
        their intended ranges (what its constructor warned of), given by the vehicle
        (:attr:`~vbi_lib.QuarterCar.notes`, ...); :attr:`notes` adds the system's own.

    Raises
    ------
    TypeError
        An entry that is not a number (text, ``None``), ``unilateral`` entries that are not
        bools.
    ValueError
        A matrix of the wrong shape, not symmetric or not (semi-)definite, a load, stiffness
        or footprint out of range, a weight outside ``vehicle_weight``
        (:data:`vbi_lib.ranges.RANGES`), or static loads that do not balance gravity.

    Warns
    -----
    OutsideValidityWarning
        A natural frequency on a rigid road outside the intended 0.5 to 50 Hz, or a weight
        outside the intended range.  A system is the general form of a vehicle: its
        frequencies have no hard limit, so limiting cases (a stiff, light wheel) can be run.
    """

    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    contact: np.ndarray
    offsets: np.ndarray
    static_loads: np.ndarray
    contact_stiffness: np.ndarray
    contact_damping: np.ndarray
    unilateral: np.ndarray
    footprint: np.ndarray
    dof_names: tuple[str, ...] = ()
    dof_units: tuple[str, ...] = ()
    name: str = field(default="")
    given_notes: tuple[str, ...] = field(default=(), repr=False)

    def __post_init__(self) -> None:
        mass = _numbers("mass", self.mass, 2)
        n = mass.shape[0]
        if n < 1 or mass.shape != (n, n):
            raise ValueError(f"mass must be a square matrix; got shape {mass.shape}")
        if n > 200:
            raise ValueError(f"mass has {n} degrees of freedom; a vehicle has at most 200")
        contact = _numbers("contact", self.contact, 2)
        n_axles = contact.shape[0]
        if n_axles < 1:
            raise ValueError("a vehicle needs at least one axle (one row of contact)")
        if n_axles > 200:
            raise ValueError(f"contact has {n_axles} axles; a vehicle has at most 200")
        arrays = {
            "mass": _matrix("mass", mass, (n, n)),
            "stiffness": _matrix("stiffness", self.stiffness, (n, n)),
            "damping": _matrix("damping", self.damping, (n, n)),
            "contact": _matrix("contact", contact, (n_axles, n)),
            "offsets": _vector("offsets", self.offsets, n_axles),
            "static_loads": _vector("static_loads", self.static_loads, n_axles),
            "contact_stiffness": _vector("contact_stiffness", self.contact_stiffness, n_axles),
            "contact_damping": _vector("contact_damping", self.contact_damping, n_axles),
            "unilateral": _vector("unilateral", self.unilateral, n_axles, bool),
            "footprint": _vector("footprint", self.footprint, n_axles),
        }
        _symmetric("mass", arrays["mass"], definite=True)
        _symmetric("stiffness", arrays["stiffness"], definite=False)
        _symmetric("damping", arrays["damping"], definite=False)
        for key, low, text in (
            ("static_loads", 0.0, "> 0 [N]"),
            ("contact_stiffness", 0.0, "> 0 [N/m]"),
        ):
            if (arrays[key] <= low).any():
                raise ValueError(f"{key}={arrays[key].tolist()} must all be {text}")
        for key in ("contact_damping", "footprint", "offsets"):
            if (arrays[key] < 0).any():
                raise ValueError(f"{key}={arrays[key].tolist()} must all be >= 0")
        if arrays["offsets"].min() != 0.0:
            raise ValueError(
                f"offsets={arrays['offsets'].tolist()} must be measured from the first axle "
                "(the smallest must be 0)"
            )
        names = tuple(self.dof_names) or tuple(f"dof {i + 1}" for i in range(n))
        units = tuple(self.dof_units) or ("m",) * n
        if len(names) != n or len(units) != n or set(units) - {"m", "rad"}:
            raise ValueError(
                f"dof_names={names!r} and dof_units={units!r} need one entry per degree of "
                f"freedom ({n}); units are 'm' or 'rad'"
            )
        for key, value in arrays.items():
            value.setflags(write=False)
            object.__setattr__(self, key, value)
        object.__setattr__(self, "dof_names", names)
        object.__setattr__(self, "dof_units", units)
        weight = "weight (the sum of static_loads)"
        check_range("vehicle_weight", self.weight, weight, warn=False)
        self._check_gravity()
        given = self.given_notes
        if isinstance(given, str) or not all(isinstance(n, str) for n in given):
            raise TypeError(f"given_notes={given!r} must be a tuple of sentences (text)")
        heavy = outside_note("vehicle_weight", self.weight, weight)
        label = self.name or "the vehicle"
        frequencies = [
            outside_note("vehicle_frequency", float(f), f"frequency {i + 1} of {label}")
            for i, f in enumerate(self.frequencies_hz)
        ]
        own = [n for n in (heavy, *frequencies) if n]
        for note in own[: 1 + bool(heavy)]:  # the weight and the first frequency outside
            warn_outside(note)
        object.__setattr__(self, "given_notes", tuple(given))
        object.__setattr__(self, "_notes", tuple(dict.fromkeys((*given, *own))))

    def _check_gravity(self) -> None:
        """The static loads must be the weight of the masses (see the module docstring)."""
        E, K, C, M = self.contact, self.stiffness, self.damping, self.mass
        n = self.n_dofs
        k_scale = max(float(np.abs(K).max()), 1e-300)
        c_scale = max(float(np.abs(C).max()), 1e-300)
        rows = np.vstack((E, K / k_scale, C / c_scale))
        target = np.concatenate((np.ones(self.n_axles), np.zeros(2 * n)))
        d = np.linalg.lstsq(rows, target, rcond=None)[0]
        if np.abs(rows @ d - target).max() > 1e-9:
            raise ValueError(
                "the vehicle cannot translate rigidly: no motion moves every contact point by 1 "
                "without stretching a suspension; check contact, stiffness and damping"
            )
        preload = E.T @ self.static_loads - GRAVITY * (M @ d)
        scale = float(self.static_loads.sum())
        if np.abs(K).max() > 0:
            u0 = np.linalg.lstsq(K, preload, rcond=None)[0]
            residual = np.abs(K @ u0 - preload).max()
        else:
            residual = np.abs(preload).max()
        if residual > 1e-9 * scale:
            total = float(GRAVITY * d @ M @ d)
            raise ValueError(
                f"static_loads={self.static_loads.tolist()} N do not balance the weight of the "
                f"masses ({total:.6g} N in all): make the loads sum to the weight and balance "
                "its moment about the centre of mass"
            )
        object.__setattr__(self, "_translation", d)

    @property
    def notes(self) -> tuple[str, ...]:
        """Every sentence on this vehicle's parameters outside their intended ranges: the
        vehicle's (:attr:`given_notes`), then the system's own (its weight and its natural
        frequencies on a rigid road).  Each crossing carries them in its ``notes`` and each
        study in its ``vehicle_notes`` column."""
        return self._notes

    @property
    def rigid_translation(self) -> np.ndarray:
        """``d``: the degrees of freedom of a rigid upward translation by 1 m, ``(n,)``.

        ``d @ M @ u / (d @ M @ d)`` is the height of the centre of mass.
        """
        return self._translation.copy()

    # ------------------------------------------------------------------ derived
    @property
    def n_dofs(self) -> int:
        """Number of degrees of freedom ``n``."""
        return int(self.mass.shape[0])

    @property
    def n_axles(self) -> int:
        """Number of contact points."""
        return int(self.contact.shape[0])

    @property
    def weight(self) -> float:
        """Total static load, the vehicle's weight [N]."""
        return float(self.static_loads.sum())

    @property
    def total_mass(self) -> float:
        """Weight over g [kg]."""
        return self.weight / GRAVITY

    @property
    def wheelbase(self) -> float:
        """Distance from the first to the last axle [m]."""
        return float(self.offsets.max())

    @property
    def has_unilateral(self) -> bool:
        """Whether any contact can leave the road."""
        return bool(self.unilateral.any())

    @cached_property
    def road_stiffness(self) -> np.ndarray:
        """``K + E^T diag(k_a) E``: the stiffness on a rigid road with every contact on [N/m]."""
        return self.stiffness + self.contact.T @ (self.contact_stiffness[:, None] * self.contact)

    @cached_property
    def mass_inverse(self) -> np.ndarray:
        """``M^-1``."""
        return np.linalg.inv(self.mass)

    @cached_property
    def _static_map(self) -> np.ndarray:
        """``(K + E^T k E)^-1 E^T diag(k)``: road heights under the axles to static ``u``."""
        return np.linalg.solve(
            self.road_stiffness, self.contact.T * self.contact_stiffness[None, :]
        )

    @cached_property
    def circular_frequencies(self) -> np.ndarray:
        """Undamped natural frequencies on a rigid road, every contact on [rad/s], increasing."""
        import scipy.linalg

        values = scipy.linalg.eigh(self.road_stiffness, self.mass, eigvals_only=True)
        result = np.sqrt(np.maximum(values, 0.0))
        result.setflags(write=False)
        return result

    @property
    def frequencies_hz(self) -> np.ndarray:
        """:attr:`circular_frequencies` in Hz."""
        return self.circular_frequencies / (2.0 * math.pi)

    def static_position(self, road: np.ndarray) -> np.ndarray:
        """Static displacement ``u`` [m, rad] on road heights ``road`` under the axles [m].

        Solves ``(K + E^T diag(k) E) u = E^T diag(k) road``: every contact loaded by its
        static load plus the spring's share of the road's unevenness.
        """
        return self._static_map @ _vector("road", road, self.n_axles)

    def __repr__(self) -> str:
        label = f"{self.name!r}, " if self.name else ""
        kind = "unilateral" if self.unilateral.all() else "bilateral"
        if self.has_unilateral and not self.unilateral.all():
            kind = "mixed"
        return (
            f"VehicleSystem({label}{self.n_dofs} dofs, {self.n_axles} axles ({kind}), "
            f"{display.short(self.weight, 'weight')}, "
            f"wheelbase {display.short(self.wheelbase, 'length')})"
        )


def stack(systems: list[VehicleSystem], positions: list[float], name: str = "") -> VehicleSystem:
    """Several vehicles as one system: block-diagonal matrices, axles shifted by ``positions``.

    ``positions[i]`` is how far the first axle of vehicle ``i`` is behind the first axle of
    vehicle 0 [m] (``positions[0] == 0``).
    """
    n = sum(s.n_dofs for s in systems)
    a = sum(s.n_axles for s in systems)
    blocks = {key: np.zeros((n, n)) for key in ("mass", "stiffness", "damping")}
    contact = np.zeros((a, n))
    i = j = 0
    for s in systems:
        for key, block in blocks.items():
            block[i : i + s.n_dofs, i : i + s.n_dofs] = getattr(s, key)
        contact[j : j + s.n_axles, i : i + s.n_dofs] = s.contact
        i += s.n_dofs
        j += s.n_axles

    def joined(key: str) -> np.ndarray:
        return np.concatenate([getattr(s, key) for s in systems])

    notes = tuple(f"vehicle {k + 1}: {note}" for k, s in enumerate(systems) for note in s.notes)
    return VehicleSystem(
        given_notes=notes,
        contact=contact,
        offsets=np.concatenate([s.offsets + p for s, p in zip(systems, positions, strict=True)]),
        static_loads=joined("static_loads"),
        contact_stiffness=joined("contact_stiffness"),
        contact_damping=joined("contact_damping"),
        unilateral=joined("unilateral"),
        footprint=joined("footprint"),
        dof_names=tuple(f"vehicle {k + 1} {d}" for k, s in enumerate(systems) for d in s.dof_names),
        dof_units=tuple(u for s in systems for u in s.dof_units),
        name=name,
        **blocks,
    )


def as_system(vehicle: object) -> VehicleSystem:
    """The :class:`VehicleSystem` of any vehicle of the library.

    Raises
    ------
    TypeError
        ``vehicle`` is not one of the library's vehicles.
    """
    if isinstance(vehicle, VehicleSystem):
        return vehicle
    system = getattr(vehicle, "system", None)
    if isinstance(system, VehicleSystem):
        return system
    shown = repr(vehicle)
    shown = shown if len(shown) <= 60 else shown[:57] + "..."
    raise TypeError(
        "vehicle must be a vbi vehicle (Vehicle, QuarterCar, IndependentAxles, RigidTruck, "
        f"Convoy or VehicleSystem), got {type(vehicle).__name__} {shown}"
    )
