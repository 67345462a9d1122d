r"""Stiffness and mass of a deck in its Ritz functions (the Rayleigh-Ritz method).

With the deflection :math:`w = \sum c_i \Phi_i` in the functions of
:mod:`vbi_lib.decks.basis`, the strain and kinetic energies are :math:`\tfrac12 c^T K c` and
:math:`\tfrac12 \dot c^T M \dot c`, and the deck's modes solve :math:`K c = \omega^2 M c`.

**Slab** (an isotropic Kirchhoff plate, :math:`D = E h^3 / 12(1-\nu^2)`):

.. math::
    U = \tfrac12 \int \kappa^T \mathbf{D}\, \kappa \, dA, \qquad
    \kappa = (w_{,xx},\; w_{,yy},\; 2 w_{,xy}), \qquad
    \mathbf{D} = D \begin{bmatrix} 1 & \nu & 0 \\ \nu & 1 & 0 \\ 0 & 0 & (1-\nu)/2 \end{bmatrix}.

In oblique coordinates (:math:`\partial_x = \partial_\xi`,
:math:`\partial_y = \partial_\eta - t\partial_\xi`) the curvatures are
:math:`\kappa = T\,(W_{,\xi\xi}, W_{,\xi\eta}, W_{,\eta\eta})` with

.. math::
    T = \begin{bmatrix} 1 & 0 & 0 \\ t^2 & -2t & 1 \\ -2t & 2 & 0 \end{bmatrix},

so :math:`K_{slab} = \sum_{ij} (T^T \mathbf{D} T)_{ij}\, A^{\xi}_{a_i a_j} \otimes
A^{\eta}_{b_i b_j}`, where :math:`A^{\xi}_{ac} = \int X^{(a)} X^{(c)T} d\xi`,
:math:`A^{\eta}_{bd} = \int Y^{(b)} Y^{(d)T} d\eta` and :math:`(a_i, b_i)` runs over
:math:`(2,0), (1,1), (0,2)`: every integral separates into one along and one across.
The kinetic energy of the slab gives :math:`M_{slab} = \rho h\, A^{\xi}_{00}\otimes A^{\eta}_{00}`.

**Girders and edge beams** are lines :math:`\eta = \eta_g` along the deck, each bending with
the slab (:math:`\tfrac12\int EI\, w_{,xx}^2\,dx`), twisting with it
(:math:`\tfrac12\int GJ\, w_{,xy}^2\,dx`, :math:`w_{,xy} = W_{,\xi\eta} - tW_{,\xi\xi}`) and
carrying their mass (:math:`\tfrac12\int m\,\dot w^2\,dx`); no eccentricity.  A girder's
:math:`EI` is its composite rigidity with its tributary slab; the slab's own share
:math:`D b` over the tributary width :math:`b` is already in the plate and is taken off it.

**Diaphragms** are lines :math:`\xi = \xi_d` parallel to the supports between the exterior
girders (AASHTO LRFD 9.7.1.3 allows them parallel to the skew up to 20 degrees).  Along such a
line :math:`d^2w/ds^2 = \cos^2\theta\, W_{,\eta\eta}` and :math:`ds = d\eta/\cos\theta`, so a
diaphragm adds :math:`EI_d \cos^3\theta\, X X^T \otimes \int Y''Y''^T d\eta` to the stiffness
and :math:`(m_d/\cos\theta)\, X X^T\otimes\int Y Y^T d\eta` to the mass.

All integrals are by Gauss-Legendre quadrature, exact for the polynomials across and to
rounding for the beam modes along (pieces shorter than a quarter wavelength).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from .basis import RitzBasis

if TYPE_CHECKING:
    from .layout import DeckLayout

__all__ = ["stiffness_and_mass"]

#: Curvature orders (d/dxi, d/deta) of (W_xixi, W_xieta, W_etaeta).
_ORDERS = ((2, 0), (1, 1), (0, 2))


def curvature_transform(tangent: float) -> np.ndarray:
    """``T`` of the module docstring: ``(w_xx, w_yy, 2 w_xy) = T (W_xixi, W_xieta, W_etaeta)``."""
    t = tangent
    return np.array([[1.0, 0.0, 0.0], [t * t, -2.0 * t, 1.0], [-2.0 * t, 2.0, 0.0]])


def stiffness_and_mass(deck: DeckLayout, basis: RitzBasis) -> tuple[np.ndarray, np.ndarray]:
    """The deck's stiffness ``K`` [N/m] and mass ``M`` [kg] matrices, ``(M Q, M Q)`` each.

    Units: with ``c`` in metres, ``c^T K c / 2`` is the strain energy [J] and
    ``c'^T M c' / 2`` the kinetic energy [J].
    """
    nu = deck.poisson
    plate = deck.flexural_rigidity * np.array(
        [[1.0, nu, 0.0], [nu, 1.0, 0.0], [0.0, 0.0, 0.5 * (1.0 - nu)]]
    )
    transform = curvature_transform(basis.tangent)
    rigidity = transform.T @ plate @ transform
    size = basis.size
    stiffness = np.zeros((size, size))
    for i, (a_i, b_i) in enumerate(_ORDERS):
        for j, (a_j, b_j) in enumerate(_ORDERS):
            if rigidity[i, j] != 0.0:
                stiffness += rigidity[i, j] * np.kron(
                    basis.along_gram(a_i, a_j), basis.across_gram(b_i, b_j)
                )
    mass = deck.slab_mass_per_area * np.kron(basis.along_gram(0, 0), basis.across_gram(0, 0))

    t = basis.tangent
    a00, a11, a22 = basis.along_gram(0, 0), basis.along_gram(1, 1), basis.along_gram(2, 2)
    for line in deck.line_members():
        y0 = basis.across_values([line.position], 0)[0]
        y1 = basis.across_values([line.position], 1)[0]
        outer00 = np.outer(y0, y0)
        if line.EI:
            stiffness += line.EI * np.kron(a22, outer00)
        if line.GJ:
            a21 = basis.along_gram(2, 1)
            cross = np.kron(a21, np.outer(y0, y1))
            stiffness += line.GJ * (
                t * t * np.kron(a22, outer00)
                - t * (cross + cross.T)
                + np.kron(a11, np.outer(y1, y1))
            )
        if line.mass_per_length:
            mass += line.mass_per_length * np.kron(a00, outer00)

    if deck.diaphragms is not None:
        cosine = 1.0 / math.sqrt(1.0 + t * t)
        low, high = deck.diaphragm_extent
        bending = basis.across_gram(2, 2, low, high)
        inertia = basis.across_gram(0, 0, low, high)
        for station in deck.diaphragm_stations:
            x0 = basis.along_values([station], 0)[0]
            outer = np.outer(x0, x0)
            stiffness += deck.diaphragms.EI * cosine**3 * np.kron(outer, bending)
            if deck.diaphragms.mass_per_length:
                mass += deck.diaphragms.mass_per_length / cosine * np.kron(outer, inertia)
    return 0.5 * (stiffness + stiffness.T), 0.5 * (mass + mass.T)
