r"""The truck as a single sprung mass (study equations 46-47 and 85).

A mass ``m_v`` on a spring ``k_v`` and a viscous damper ``c_v`` whose lower end follows the
road (profile plus bridge deflection under the wheel).  Its undamped body-bounce frequency is
:math:`f_v = \sqrt{k_v / m_v} / 2\pi` and its damping ratio
:math:`\zeta_v = c_v / (2 \sqrt{k_v m_v})`.  Given a frequency, (85) gives
:math:`k_v = m_v \omega_v^2` and :math:`c_v = 2 \zeta_v m_v \omega_v`; when the frequency
given is the damped one, :math:`\omega_v = 2\pi f_d / \sqrt{1 - \zeta_v^2}`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from .. import _validation as check
from .. import display
from ..ranges import check_range, outside_note, warn_outside
from ..units import g
from .system import VehicleSystem


@dataclass(frozen=True)
class Vehicle:
    """A sprung mass: mass [kg], suspension stiffness [N/m] and damping coefficient [N s/m].

    Raises
    ------
    TypeError
        A value that is not a number.
    ValueError
        A mass, damping ratio or bounce frequency outside its range of validity
        (:data:`vbi_lib.ranges.RANGES`: ``vehicle_mass``, ``vehicle_damping_ratio``,
        ``vehicle_frequency``), a stiffness not > 0 or a damping < 0.

    Warns
    -----
    OutsideValidityWarning
        A mass or damping ratio outside the intended range (the frequency is judged when the
        vehicle's :attr:`system` is built).

    Examples
    --------
    Table 2.13.1's vehicle: 100 slinch on 63165.5 lb/in bounces at 4.00 Hz.

    >>> from vbi_lib import units as u
    >>> v = Vehicle(100 * u.slinch, 63165.5 * u.lbf / u.inch, 0.0)
    >>> round(v.frequency_hz, 2)
    4.0
    """

    mass: float
    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        mass = check_range("vehicle_mass", self.mass, "mass", warn=False)
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "stiffness", check.positive("stiffness", self.stiffness))
        object.__setattr__(self, "damping", check.non_negative("damping", self.damping))
        zeta = check.damping_ratio("damping_ratio (from damping)", self.damping_ratio)
        check_range("vehicle_damping_ratio", zeta, "damping_ratio (from damping)", warn=False)
        check_range(
            "vehicle_frequency", self.frequency_hz, "frequency_hz (from mass and stiffness)",
            warn=False,
        )  # fmt: skip
        for note in self.notes:
            warn_outside(note)

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on the mass and damping ratio outside their intended ranges (what the
        constructor warns of); the frequency is judged by :attr:`system`, whose
        :attr:`~vbi_lib.vehicles.VehicleSystem.notes` hold these and its own."""
        notes = (
            outside_note("vehicle_mass", self.mass, "mass"),
            outside_note("vehicle_damping_ratio", self.damping_ratio,
                         "damping_ratio (from damping)"),
        )  # fmt: skip
        return tuple(n for n in notes if n)

    @classmethod
    def from_frequency(
        cls,
        mass: float,
        frequency_hz: float,
        damping_ratio: float = 0.1,
        damped: bool = False,
    ) -> Vehicle:
        """A sprung mass with a given body-bounce frequency and damping ratio (85).

        Parameters
        ----------
        mass
            Sprung mass [kg].
        frequency_hz
            Body-bounce frequency [Hz]; the undamped one unless ``damped=True``.
        damping_ratio
            Fraction of critical damping, in [0, 1).
        damped
            ``True`` when ``frequency_hz`` is the damped frequency ``f_d`` (Table 2.13.9).

        Examples
        --------
        Table 2.13.9, the 40 ft bridges' truck: 200 slinch, damped 10.5 Hz, 10 %.

        >>> from vbi_lib import units as u
        >>> v = Vehicle.from_frequency(200 * u.slinch, 10.5, 0.10, damped=True)
        >>> round(v.stiffness / (u.lbf / u.inch), -1), round(v.damping / (u.lbf / u.inch), 2)
        (879290.0, 2652.23)
        """
        mass = check_range("vehicle_mass", mass, "mass", warn=False)
        frequency = check_range("vehicle_frequency", frequency_hz, "frequency_hz", warn=False)
        zeta = check.damping_ratio("damping_ratio", damping_ratio)
        zeta = check_range("vehicle_damping_ratio", zeta, "damping_ratio", warn=False)
        omega = 2.0 * math.pi * frequency
        if check.flag("damped", damped):
            omega /= math.sqrt(1.0 - zeta**2)
        return cls(mass, mass * omega**2, 2.0 * zeta * mass * omega)

    @property
    def circular_frequency(self) -> float:
        """Undamped ``omega_v = sqrt(k_v / m_v)`` [rad/s]."""
        return math.sqrt(self.stiffness / self.mass)

    @property
    def frequency_hz(self) -> float:
        """Undamped body-bounce frequency [Hz]."""
        return self.circular_frequency / (2.0 * math.pi)

    @property
    def damping_ratio(self) -> float:
        """``c_v / (2 sqrt(k_v m_v))``."""
        return self.damping / (2.0 * math.sqrt(self.stiffness * self.mass))

    @property
    def damped_frequency_hz(self) -> float:
        """Damped frequency ``f_v sqrt(1 - zeta^2)`` [Hz]."""
        return self.frequency_hz * math.sqrt(1.0 - self.damping_ratio**2)

    @property
    def weight(self) -> float:
        """Static weight ``m_v g`` [N]."""
        return self.mass * g

    @cached_property
    def system(self) -> VehicleSystem:
        """The sprung mass as a :class:`~vbi_lib.vehicles.VehicleSystem`: one degree of freedom,
        one bilateral contact whose spring and damper are the suspension, no footprint."""
        return VehicleSystem(
            mass=[[self.mass]],
            stiffness=[[0.0]],
            damping=[[0.0]],
            contact=[[1.0]],
            offsets=[0.0],
            static_loads=[self.weight],
            contact_stiffness=[self.stiffness],
            contact_damping=[self.damping],
            unilateral=[False],
            footprint=[0.0],
            dof_names=("sprung mass",),
            name="sprung mass",
            given_notes=self.notes,
        )

    def __repr__(self) -> str:
        return (
            f"Vehicle(m = {display.short(self.mass, 'mass')} "
            f"(weight {display.short(self.weight, 'weight')}), f = {self.frequency_hz:.2f} Hz, "
            f"zeta = {self.damping_ratio:.1%})"
        )
