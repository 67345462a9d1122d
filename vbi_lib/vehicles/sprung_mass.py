r"""The truck as a single sprung mass (study equations 46-47 and 85).

A mass ``m_v`` on a spring ``k_v`` and a viscous damper ``c_v`` whose lower end follows the
road (profile plus bridge deflection under the wheel).  Its undamped body-bounce frequency is
:math:`f_v = \sqrt{k_v / m_v} / 2\pi` and its damping ratio
:math:`\zeta_v = c_v / (2 \sqrt{k_v m_v})`.  Given a frequency, (85) gives
:math:`k_v = m_v \omega_v^2` and :math:`c_v = 2 \zeta_v m_v \omega_v`; when the frequency
given is the damped one, :math:`\omega_v = 2\pi f_d / \sqrt{1 - \zeta_v^2}`.

A damping ratio of 1 or more is a valid suspension (critically damped or overdamped: it
returns to rest without oscillating; VBI-2D's verification vehicle, 5750 kg on 1595 kN/m
and 400 kN s/m, is damped 2.09 times critical).  It has no damped frequency; both crossing
models integrate it as any other (their default steps follow the eigenvalues of the
coupled system, whose fast real root grows as :math:`(\zeta_v + \sqrt{\zeta_v^2 - 1})\,
\omega_v`).
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

    Parameters
    ----------
    mass, stiffness, damping
        ``m_v`` [kg], ``k_v`` [N/m] > 0, ``c_v`` [N s/m] >= 0 (any damping ratio).
    footprint
        Contact length [m] over which the wheel averages the road
        (:mod:`~vbi_lib.vehicles.footprint`); 0 (default) is the study's point contact, which
        reproduces its tables.  A point contact's damper force over a road feature sharper
        than the profile's sampling is set by the sampling; a crossing says so
        (:func:`~vbi_lib.vehicles.footprint.unresolved_road_note`).

    Raises
    ------
    TypeError
        A value that is not a number.
    ValueError
        A mass or bounce frequency outside its range of validity
        (:data:`vbi_lib.ranges.RANGES`: ``vehicle_mass``, ``vehicle_frequency``), a stiffness
        not > 0, a damping < 0, a footprint outside ``footprint``'s range.

    Warns
    -----
    OutsideValidityWarning
        A mass, damping ratio (``vehicle_damping_ratio``: above 0.5, overdamped suspensions
        included) or footprint outside the intended range (the frequency is judged when the
        vehicle's :attr:`system` is built).

    Examples
    --------
    Table 2.13.1's vehicle: 100 slinch on 63165.5 lb/in bounces at 4.00 Hz.

    >>> from vbi_lib import units as u
    >>> v = Vehicle(100 * u.slinch, 63165.5 * u.lbf / u.inch, 0.0)
    >>> round(v.frequency_hz, 2)
    4.0

    VBI-2D's verification vehicle is overdamped (accepted, with a warning that 2.09 lies
    outside the intended range of suspension damping):

    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     round(Vehicle(5750.0, 1595e3, 4e5).damping_ratio, 2)
    2.09
    """

    mass: float
    stiffness: float
    damping: float = 0.0
    footprint: float = 0.0

    def __post_init__(self) -> None:
        mass = check_range("vehicle_mass", self.mass, "mass", warn=False)
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "stiffness", check.positive("stiffness", self.stiffness))
        object.__setattr__(self, "damping", check.non_negative("damping", self.damping))
        footprint = check_range("footprint", self.footprint, warn=False)
        object.__setattr__(self, "footprint", footprint)
        # any ratio >= 0: 1 or more is an overdamped suspension (noted and warned of)
        check_range("vehicle_damping_ratio", self.damping_ratio, "damping_ratio (from damping)",
                    warn=False)  # fmt: skip
        check_range(
            "vehicle_frequency", self.frequency_hz, "frequency_hz (from mass and stiffness)",
            warn=False,
        )  # fmt: skip
        for note in self.notes:
            warn_outside(note)

    @property
    def notes(self) -> tuple[str, ...]:
        """Sentences on the mass, damping ratio and footprint outside their intended ranges
        (what the constructor warns of); the frequency is judged by :attr:`system`, whose
        :attr:`~vbi_lib.vehicles.VehicleSystem.notes` hold these and its own."""
        notes = (
            outside_note("vehicle_mass", self.mass, "mass"),
            outside_note("vehicle_damping_ratio", self.damping_ratio,
                         "damping_ratio (from damping)"),
            outside_note("footprint", self.footprint, "footprint"),
        )  # fmt: skip
        return tuple(n for n in notes if n)

    @classmethod
    def from_frequency(
        cls,
        mass: float,
        frequency_hz: float,
        damping_ratio: float = 0.1,
        damped: bool = False,
        footprint: float = 0.0,
    ) -> Vehicle:
        """A sprung mass with a given body-bounce frequency and damping ratio (85).

        Parameters
        ----------
        mass
            Sprung mass [kg].
        frequency_hz
            Body-bounce frequency [Hz]; the undamped one unless ``damped=True``.
        damping_ratio
            Fraction of critical damping, >= 0 (1 or more: an overdamped suspension).
        damped
            ``True`` when ``frequency_hz`` is the damped frequency ``f_d`` (Table 2.13.9);
            only for ``damping_ratio < 1`` (an overdamped suspension has no damped
            frequency).
        footprint
            Contact length [m] (see the class); 0 by default, the study's point contact.

        Raises
        ------
        ValueError
            A mass, frequency or damping ratio outside its range
            (:data:`vbi_lib.ranges.RANGES`), or ``damped=True`` with ``damping_ratio >= 1``.

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
        zeta = check_range("vehicle_damping_ratio", damping_ratio, "damping_ratio", warn=False)
        omega = 2.0 * math.pi * frequency
        if check.flag("damped", damped):
            if zeta >= 1.0:
                raise ValueError(
                    f"damped=True with damping_ratio={damping_ratio!r}: a suspension damped at "
                    "or above critical (1) does not oscillate and has no damped frequency; give "
                    "the undamped frequency sqrt(k/m)/(2 pi) with damped=False"
                )
            omega /= math.sqrt(1.0 - zeta**2)
        damping = 2.0 * zeta * mass * omega
        if not math.isfinite(damping):
            raise ValueError(
                f"damping_ratio={damping_ratio!r} gives a damping coefficient too large to hold "
                f"({damping!r} N s/m) with mass={mass!r} kg at {frequency!r} Hz; give a smaller "
                "damping_ratio"
            )
        return cls(mass, mass * omega**2, damping, footprint)

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
        """Damped frequency ``f_v sqrt(1 - zeta^2)`` [Hz].

        Raises
        ------
        ValueError
            The suspension is damped at or above critical (``damping_ratio >= 1``): it does not
            oscillate and has no damped frequency.
        """
        zeta = self.damping_ratio
        if zeta >= 1.0:
            raise ValueError(
                f"damping_ratio={zeta:.4g} is at or above critical (1): this suspension does not "
                "oscillate and has no damped frequency; use frequency_hz (undamped)"
            )
        return self.frequency_hz * math.sqrt(1.0 - zeta**2)

    @property
    def weight(self) -> float:
        """Static weight ``m_v g`` [N]."""
        return self.mass * g

    @cached_property
    def system(self) -> VehicleSystem:
        """The sprung mass as a :class:`~vbi_lib.vehicles.VehicleSystem`: one degree of freedom,
        one bilateral contact whose spring and damper are the suspension, and its footprint."""
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
            footprint=[self.footprint],
            dof_names=("sprung mass",),
            name="sprung mass",
            given_notes=self.notes,
        )

    def __repr__(self) -> str:
        contact = (
            f", footprint = {display.short(self.footprint, 'spacing')}" if self.footprint else ""
        )
        return (
            f"Vehicle(m = {display.short(self.mass, 'mass')} "
            f"(weight {display.short(self.weight, 'weight')}), f = {self.frequency_hz:.2f} Hz, "
            f"zeta = {self.damping_ratio:.1%}{contact})"
        )
