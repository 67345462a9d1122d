"""vbi_lib: dynamic amplification of bridges under a moving truck.

The library behind the *vbi* book.  SI units throughout; :mod:`vbi_lib.units` converts.

>>> import vbi_lib as vbi
>>> from vbi_lib import units as u
>>> bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
>>> round(bridge.first_frequency_hz, 2)
3.99
"""

from . import amplification, monitoring, units
from .bridges import Bridge, shape_function_error
from .profiles import Profile, max_sample_spacing
from .simulation import BatchResult, Crossing, simulate, simulate_many, state_matrices
from .vehicles import Vehicle

__all__ = [
    "BatchResult",
    "Bridge",
    "Crossing",
    "Profile",
    "Vehicle",
    "amplification",
    "max_sample_spacing",
    "monitoring",
    "shape_function_error",
    "simulate",
    "simulate_many",
    "state_matrices",
    "units",
]

__version__ = "0.1.0"
