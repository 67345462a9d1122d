"""vbi_lib: dynamic amplification of bridges under a moving truck.

The library behind the *vbi* book.  SI units throughout; :mod:`vbi_lib.units` converts.

>>> import vbi_lib as vbi
>>> from vbi_lib import units as u
>>> bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
>>> round(bridge.first_frequency_hz, 2)
3.99
"""

from . import amplification, closed_forms, monitoring, roughness, studies, study_data, units
from .bridges import Bridge, reference_beam, shape_function_error
from .modal import ModalCrossing, beam_modes, simulate_modal, simulate_modal_many
from .profile_files import ErdFile, ProfileFileError, read_erd, read_profile
from .profiles import Profile, iso8608_class, max_sample_spacing
from .roughness import contact_force_amplification, fit_iso8608, iri, profile_spectrum
from .simulation import BatchResult, Crossing, simulate, simulate_many, state_matrices
from .vehicles import Vehicle

__all__ = [
    "BatchResult",
    "Bridge",
    "Crossing",
    "ModalCrossing",
    "beam_modes",
    "closed_forms",
    "reference_beam",
    "simulate_modal",
    "simulate_modal_many",
    "ErdFile",
    "Profile",
    "ProfileFileError",
    "Vehicle",
    "amplification",
    "contact_force_amplification",
    "fit_iso8608",
    "iri",
    "iso8608_class",
    "max_sample_spacing",
    "monitoring",
    "profile_spectrum",
    "read_erd",
    "read_profile",
    "roughness",
    "shape_function_error",
    "simulate",
    "simulate_many",
    "state_matrices",
    "studies",
    "study_data",
    "units",
]

__version__ = "0.1.0"
