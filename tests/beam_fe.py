"""A small Euler-Bernoulli beam finite-element model, the tests' independent reference.

Hermite cubic elements (exact statics at the nodes under nodal loads), consistent mass
matrices for the free vibration, pinned supports (zero deflection) at given stations.
Nothing here comes from the library.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import eigh
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import splu


def element_matrices(h: float, ei: float, mbar: float) -> tuple[np.ndarray, np.ndarray]:
    """Stiffness and consistent mass of one element of length ``h`` (dofs w1, t1, w2, t2)."""
    k = (ei / h**3) * np.array(
        [
            [12, 6 * h, -12, 6 * h],
            [6 * h, 4 * h * h, -6 * h, 2 * h * h],
            [-12, -6 * h, 12, -6 * h],
            [6 * h, 2 * h * h, -6 * h, 4 * h * h],
        ]
    )
    m = (mbar * h / 420.0) * np.array(
        [
            [156, 22 * h, 54, -13 * h],
            [22 * h, 4 * h * h, 13 * h, -3 * h * h],
            [54, 13 * h, 156, -22 * h],
            [-13 * h, -3 * h * h, -22 * h, 4 * h * h],
        ]
    )
    return k, m


class Beam:
    """A beam over ``supports`` (stations [m]) with nodes at every ``required`` station.

    Between required nodes the mesh is filled with elements no longer than ``element``;
    filling nodes closer than a quarter element to a required one are dropped, so no element
    is tiny (tiny elements would spoil the conditioning).
    """

    def __init__(self, supports, required, ei: float, mbar: float = 1.0, element=None) -> None:  # noqa: ANN001
        self.supports = np.asarray(supports, dtype=float)
        required = np.asarray(required, dtype=float)
        # stations within rounding of a support are that support (no zero-length element)
        near = np.abs(required[:, None] - self.supports[None, :]) < 1e-9 * self.supports[-1]
        required = required[~near.any(axis=1)]
        fixed = np.unique(np.concatenate([required, self.supports]))
        fixed = fixed[np.concatenate([[True], np.diff(fixed) > 1e-9 * fixed[-1]])]
        if element is not None:
            fill = np.linspace(0.0, fixed[-1], int(np.ceil(fixed[-1] / element)) + 1)
            gap = np.min(np.abs(fill[:, None] - fixed[None, :]), axis=1)
            fixed = np.unique(np.concatenate([fixed, fill[gap > 0.25 * element]]))
        self.nodes = fixed
        self.ei = ei
        dof = 2 * self.nodes.size
        rows, cols, kv, mv = [], [], [], []
        index = np.arange(4)
        for i, h in enumerate(np.diff(self.nodes)):
            k, m = element_matrices(h, ei, mbar)
            r, c = np.meshgrid(2 * i + index, 2 * i + index, indexing="ij")
            rows.append(r.ravel())
            cols.append(c.ravel())
            kv.append(k.ravel())
            mv.append(m.ravel())
        rows, cols = np.concatenate(rows), np.concatenate(cols)
        self.K = coo_matrix((np.concatenate(kv), (rows, cols)), shape=(dof, dof)).tocsc()
        self.M = coo_matrix((np.concatenate(mv), (rows, cols)), shape=(dof, dof)).tocsc()
        self.fixed = np.array([2 * self.node(s) for s in self.supports])
        self.free = np.setdiff1d(np.arange(dof), self.fixed)

    def node(self, x: float) -> int:
        i = int(np.argmin(np.abs(self.nodes - x)))
        assert abs(self.nodes[i] - x) < 1e-9 * self.nodes[-1], f"no node at {x}"
        return i

    def frequencies(self, count: int) -> tuple[np.ndarray, np.ndarray]:
        """First ``count`` circular frequencies [rad/s] and the nodal deflections of the
        mass-normalised modes, ``(n_nodes, count)`` (dense eigensolver: small meshes)."""
        free = self.free
        k = self.K[free][:, free].toarray()
        m = self.M[free][:, free].toarray()
        w2, vectors = eigh(k, m, subset_by_index=[0, count - 1])
        full = np.zeros((self.K.shape[0], count))
        full[free] = vectors
        return np.sqrt(w2), full[0::2]

    def influence(self, loads_at: np.ndarray, sections: np.ndarray) -> tuple[np.ndarray, ...]:
        """Deflection (down), moment (sagging) and shear (dM/dx, left value; right at 0) at
        the sections under a unit load at each node of ``loads_at``; each ``(n_loads, n_s)``.

        The deflection is the nodal solution; moment and shear come by statics from the
        support reactions of the FE solution.
        """
        free = self.free
        lu = splu(self.K[free][:, free].tocsc())
        at_sections = [2 * self.node(x) for x in sections]
        w = np.empty((loads_at.size, sections.size))
        reactions = np.empty((self.supports.size, loads_at.size))
        for start in range(0, loads_at.size, 500):  # a few hundred load cases at a time
            block = loads_at[start : start + 500]
            rhs = np.zeros((self.K.shape[0], block.size))
            rhs[[2 * self.node(a) for a in block], np.arange(block.size)] = 1.0
            d = np.zeros_like(rhs)
            d[free] = lu.solve(rhs[free])
            reactions[:, start : start + block.size] = -(self.K @ d - rhs)[self.fixed]
            w[start : start + block.size] = d[at_sections].T
        x = sections[None, :]
        a = loads_at[:, None]
        moment = -np.where(x > a, x - a, 0.0)
        shear = -np.where((x > a) | ((x == 0) & (a == 0)), 1.0, 0.0)
        for r, s in zip(reactions, self.supports, strict=True):
            moment = moment + r[:, None] * np.where(s < x, x - s, 0.0)
            shear = shear + r[:, None] * np.where((s < x) | ((s == 0) & (x == 0)), 1.0, 0.0)
        return w, moment, shear
