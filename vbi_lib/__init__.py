"""vbi_lib: dynamic amplification of bridges under a moving truck.

The library behind the *vbi* book.  SI units throughout; :mod:`vbi_lib.units` converts and
:mod:`vbi_lib.display` chooses how results are shown.

>>> import vbi_lib as vbi
>>> from vbi_lib import units as u
>>> bridge = vbi.Bridge.from_midspan_stiffness(100 * u.ft, 1, 497527 * u.lbf / u.inch, 3.99)
>>> round(bridge.first_frequency_hz, 2)
3.99
"""

from . import (
    amplification,
    beam_statics,
    closed_forms,
    decks,
    display,
    models,
    monitoring,
    ranges,
    roughness,
    studies,
    study_data,
    units,
    vehicles,
)
from .bridges import Bridge, reference_beam, shape_function_error
from .decks import Deck
from .models import (
    MODELS,
    BatchResult,
    Crossing,
    ModalCrossing,
    OneCoordinateCrossing,
    simulate,
    simulate_many,
    state_matrices,
)
from .modes import BeamModes, beam_modes
from .profile_files import ErdFile, ProfileFileError, read_erd, read_profile
from .profiles import Profile, iso8608_class, max_sample_spacing
from .roughness import fit_iso8608, iri, profile_spectrum
from .validity import (
    ContactLossWarning,
    OutsideValidityWarning,
    TruncationWarning,
    UnresolvedRoadWarning,
    VbiWarning,
)
from .vehicle_metrics import contact_force_amplification
from .vehicles import QuarterCar, Vehicle, VehicleSystem

__all__ = [
    "MODELS",
    "BatchResult",
    "BeamModes",
    "Bridge",
    "ContactLossWarning",
    "Crossing",
    "Deck",
    "ErdFile",
    "ModalCrossing",
    "OneCoordinateCrossing",
    "OutsideValidityWarning",
    "Profile",
    "ProfileFileError",
    "QuarterCar",
    "TruncationWarning",
    "UnresolvedRoadWarning",
    "VbiWarning",
    "Vehicle",
    "VehicleSystem",
    "amplification",
    "beam_modes",
    "beam_statics",
    "closed_forms",
    "contact_force_amplification",
    "decks",
    "display",
    "fit_iso8608",
    "iri",
    "iso8608_class",
    "max_sample_spacing",
    "models",
    "monitoring",
    "profile_spectrum",
    "ranges",
    "read_erd",
    "read_profile",
    "reference_beam",
    "roughness",
    "shape_function_error",
    "simulate",
    "simulate_many",
    "state_matrices",
    "studies",
    "study_data",
    "units",
    "vehicles",
]

__version__ = "0.2.0"
