"""An independent plate finite-element model of a deck: the tests' reference for its statics.

Nothing here comes from the library.  The slab is meshed with Bogner-Fox-Schmit elements
(the conforming 16-dof plate rectangle: bicubic Hermite, nodal w, w_a, w_b, w_ab in the
mesh's own coordinates ``a`` along and ``b`` across), on a parallelogram mesh for a skewed
deck: the map from ``(a, b)`` to the plan ``(x, y)`` is affine, ``x = a + t b, y = b``, so
the elements stay C1-conforming.  Cartesian curvatures come from the chain rule of that map,
``H_xy = J^-T H_ab J^-1`` (written out numerically here, not by hand).  Girders and edge
beams are Hermite beam elements along mesh lines ``b = const`` (bending w_xx and twist w_xy,
both from the chain rule); diaphragms are beam elements along the lines ``a = const``,
bending in their own direction.  Supports: w = 0 and its derivative along the support line
(w_b) at every node on it.  Loads at nodes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import spsolve

_GAUSS = np.polynomial.legendre.leggauss(4)


def _hermite(r: np.ndarray, h: float, order: int) -> np.ndarray:
    """The four cubic Hermite functions on an interval of length h, at r in [0, 1], d^k/ds^k."""
    if order == 0:
        return np.array([1 - 3 * r**2 + 2 * r**3, h * (r - 2 * r**2 + r**3), 3 * r**2 - 2 * r**3,
                         h * (-(r**2) + r**3)])  # fmt: skip
    if order == 1:
        return np.array([-6 * r + 6 * r**2, h * (1 - 4 * r + 3 * r**2), 6 * r - 6 * r**2,
                         h * (-2 * r + 3 * r**2)]) / h  # fmt: skip
    return np.array([-6 + 12 * r, h * (-4 + 6 * r), 6 - 12 * r, h * (-2 + 6 * r)]) / h**2


@dataclass
class Line:
    """A beam along the mesh line ``b = position`` (girder, edge beam)."""

    position: float
    EI: float
    GJ: float = 0.0
    mass: float = 0.0


@dataclass
class Cross:
    """A diaphragm along the mesh line ``a = position`` from ``b = low`` to ``b = high``."""

    position: float
    low: float
    high: float
    EI: float
    mass: float = 0.0


class PlateFE:
    """A deck meshed on the grid ``a_nodes`` x ``b_nodes`` (see the module docstring)."""

    def __init__(self, a_nodes, b_nodes, D, nu, rho_h, tangent, supports,
                 lines=(), crosses=()) -> None:  # fmt: skip
        self.a = np.asarray(a_nodes, float)
        self.b = np.asarray(b_nodes, float)
        self.t = float(tangent)
        self.nodes = self.a.size * self.b.size
        jac = np.array([[1.0, self.t], [0.0, 1.0]])  # columns: d(x, y)/da, d(x, y)/db
        self.jinv = np.linalg.inv(jac)
        self.det = abs(np.linalg.det(jac))
        rows, cols, kv, mv = [], [], [], []
        plate = D * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
        for i in range(self.a.size - 1):
            for j in range(self.b.size - 1):
                dofs = self._element_dofs(i, j)
                ke, me = self._plate(self.a[i + 1] - self.a[i], self.b[j + 1] - self.b[j],
                                     plate, rho_h)  # fmt: skip
                self._add(rows, cols, kv, mv, dofs, ke, me)
        for line in lines:
            j = self._index(self.b, line.position)
            for i in range(self.a.size - 1):
                dofs, ke, me = self._line(i, j, line)
                self._add(rows, cols, kv, mv, dofs, ke, me)
        for cross in crosses:
            i = self._index(self.a, cross.position)
            lo, hi = self._index(self.b, cross.low), self._index(self.b, cross.high)
            for j in range(lo, hi):
                dofs, ke, me = self._cross(i, j, cross)
                self._add(rows, cols, kv, mv, dofs, ke, me)
        n = 4 * self.nodes
        self.K = coo_matrix((kv, (rows, cols)), shape=(n, n)).tocsr()
        self.M = coo_matrix((mv, (rows, cols)), shape=(n, n)).tocsr()
        fixed = []
        for s in supports:
            i = self._index(self.a, s)
            for j in range(self.b.size):
                node = self._node(i, j)
                fixed += [4 * node, 4 * node + 2]  # w and w_b along the support line
        self.free = np.setdiff1d(np.arange(n), fixed)

    @staticmethod
    def _index(grid: np.ndarray, value: float) -> int:
        i = int(np.argmin(abs(grid - value)))
        if abs(grid[i] - value) > 1e-9 * max(1.0, abs(value)):
            raise ValueError(f"{value} is not a mesh line")
        return i

    def _node(self, i: int, j: int) -> int:
        return i * self.b.size + j

    def _element_dofs(self, i: int, j: int) -> np.ndarray:
        out = []
        for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
            node = self._node(i + di, j + dj)
            out += [4 * node + k for k in range(4)]
        return np.array(out)

    @staticmethod
    def _add(rows, cols, kv, mv, dofs, ke, me) -> None:  # noqa: ANN001
        r, c = np.meshgrid(dofs, dofs, indexing="ij")
        rows += r.ravel().tolist()
        cols += c.ravel().tolist()
        kv += ke.ravel().tolist()
        mv += me.ravel().tolist()

    def _functions(
        self, ra: float, rb: float, ha: float, hb: float, oa: int, ob: int
    ) -> np.ndarray:
        """d^oa/da d^ob/db of the 16 functions (element dof order)."""
        fa, fb = _hermite(ra, ha, oa), _hermite(rb, hb, ob)
        out = []
        for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
            # node dofs w, w_a, w_b, w_ab: (value|slope in a) x (value|slope in b)
            for pa, pb in ((0, 0), (1, 0), (0, 1), (1, 1)):
                out.append(fa[2 * di + pa] * fb[2 * dj + pb])
        return np.array(out)

    def _cartesian_hessian(self, haa, hab, hbb):  # noqa: ANN001, ANN202
        """(w_xx, w_yy, w_xy) rows from the mesh-coordinate second derivatives (chain rule)."""
        ji = self.jinv

        # H_xy = J^-T H_ab J^-1, entry (p, q) = sum_kl ji[k, p] H[k, l] ji[l, q]
        def entry(p: int, q: int) -> np.ndarray:
            return (ji[0, p] * ji[0, q] * haa + (ji[0, p] * ji[1, q] + ji[1, p] * ji[0, q]) * hab
                    + ji[1, p] * ji[1, q] * hbb)  # fmt: skip

        return entry(0, 0), entry(1, 1), entry(0, 1)

    def _plate(self, ha: float, hb: float, plate: np.ndarray, rho_h: float):  # noqa: ANN202
        nodes, weights = _GAUSS
        ke = np.zeros((16, 16))
        me = np.zeros((16, 16))
        for ga, wa in zip(nodes, weights, strict=True):
            for gb, wb in zip(nodes, weights, strict=True):
                ra, rb = 0.5 * (ga + 1), 0.5 * (gb + 1)
                scale = 0.25 * wa * wb * ha * hb * self.det
                haa = self._functions(ra, rb, ha, hb, 2, 0)
                hab = self._functions(ra, rb, ha, hb, 1, 1)
                hbb = self._functions(ra, rb, ha, hb, 0, 2)
                wxx, wyy, wxy = self._cartesian_hessian(haa, hab, hbb)
                b = np.vstack([wxx, wyy, 2 * wxy])
                ke += scale * b.T @ plate @ b
                n = self._functions(ra, rb, ha, hb, 0, 0)
                me += scale * rho_h * np.outer(n, n)
        return ke, me

    def _line(self, i: int, j: int, line: Line):  # noqa: ANN202
        """A beam along b = b[j] between nodes i and i + 1: dofs w, w_a, w_b, w_ab of both."""
        n0, n1 = self._node(i, j), self._node(i + 1, j)
        dofs = np.array([4 * n0 + k for k in range(4)] + [4 * n1 + k for k in range(4)])
        h = self.a[i + 1] - self.a[i]
        direction = np.array([1.0, 0.0])  # the line in the plan: d(x, y)/da
        length = np.linalg.norm(direction)
        nodes, weights = _GAUSS
        ke = np.zeros((8, 8))
        me = np.zeros((8, 8))
        ji = self.jinv
        ex, ey = ji @ np.array([1.0, 0.0]), ji @ np.array([0.0, 1.0])
        for g, w in zip(nodes, weights, strict=True):
            r = 0.5 * (g + 1)
            f0, f1, f2 = _hermite(r, h, 0), _hermite(r, h, 1), _hermite(r, h, 2)
            # along the edge: w(a) from (w, w_a), w_b(a) from (w_b, w_ab)
            w_aa = np.zeros(8)
            w_ab = np.zeros(8)
            val = np.zeros(8)
            for node, base in ((0, 0), (1, 4)):
                w_aa[base + 0], w_aa[base + 1] = f2[2 * node], f2[2 * node + 1]
                w_ab[base + 2], w_ab[base + 3] = f1[2 * node], f1[2 * node + 1]
                val[base + 0], val[base + 1] = f0[2 * node], f0[2 * node + 1]

            wxx, wxy = (_second(ex, v, w_aa, w_ab) for v in (ex, ey))
            scale = 0.5 * w * h * length
            ke += scale * (line.EI * np.outer(wxx, wxx) + line.GJ * np.outer(wxy, wxy))
            me += scale * line.mass * np.outer(val, val)
        return dofs, ke, me

    def _cross(self, i: int, j: int, cross: Cross):  # noqa: ANN202
        """A diaphragm along a = a[i] between nodes j and j + 1, bending in its own direction."""
        n0, n1 = self._node(i, j), self._node(i, j + 1)
        dofs = np.array([4 * n0 + k for k in range(4)] + [4 * n1 + k for k in range(4)])
        h = self.b[j + 1] - self.b[j]
        direction = np.array([self.t, 1.0])  # d(x, y)/db
        length = np.linalg.norm(direction)
        e = self.jinv @ (direction / length)  # the unit direction in mesh coordinates
        if abs(e[0]) > 1e-12:
            raise ValueError("a line along b needs w_aa: not on the edge")
        nodes, weights = _GAUSS
        ke = np.zeros((8, 8))
        me = np.zeros((8, 8))
        for g, w in zip(nodes, weights, strict=True):
            r = 0.5 * (g + 1)
            f0, f2 = _hermite(r, h, 0), _hermite(r, h, 2)
            w_bb = np.zeros(8)
            val = np.zeros(8)
            for node, base in ((0, 0), (1, 4)):
                w_bb[base + 0], w_bb[base + 2] = f2[2 * node], f2[2 * node + 1]
                val[base + 0], val[base + 2] = f0[2 * node], f0[2 * node + 1]
            curvature = e[1] ** 2 * w_bb
            scale = 0.5 * w * h * length
            ke += scale * cross.EI * np.outer(curvature, curvature)
            me += scale * cross.mass * np.outer(val, val)
        return dofs, ke, me

    def static(self, loads: list[tuple[float, float, float]]) -> np.ndarray:
        """Nodal dofs under point loads ``(a, b, force)`` at nodes (downward positive w)."""
        f = np.zeros(4 * self.nodes)
        for a, b, force in loads:
            node = self._node(self._index(self.a, a), self._index(self.b, b))
            f[4 * node] += force
        u = np.zeros_like(f)
        u[self.free] = spsolve(self.K[self.free][:, self.free].tocsc(), f[self.free])
        return u

    def deflection(self, u: np.ndarray, a: float, b: float) -> float:
        return float(u[4 * self._node(self._index(self.a, a), self._index(self.b, b))])

    def frequencies_hz(self, count: int) -> np.ndarray:
        """The first ``count`` natural frequencies [Hz] (shift-invert Lanczos about 0)."""
        from scipy.sparse.linalg import eigsh

        k = self.K[self.free][:, self.free].tocsc()
        m = self.M[self.free][:, self.free].tocsc()
        values = eigsh(k, count, m, sigma=0.0, which="LM", return_eigenvectors=False)
        return np.sort(np.sqrt(values)) / (2 * np.pi)


def _second(u: np.ndarray, v: np.ndarray, w_aa: np.ndarray, w_ab: np.ndarray) -> np.ndarray:
    """u^T H v from w_aa and w_ab (a line along a has no w_bb on its edge)."""
    if abs(u[1] * v[1]) > 1e-14:
        raise ValueError("a line along a needs w_bb: not on the edge")
    return u[0] * v[0] * w_aa + (u[0] * v[1] + u[1] * v[0]) * w_ab


def grid(length: float, required: list[float], pieces: int) -> np.ndarray:
    """Nodes from 0 to ``length`` including ``required``, no gap above ``length / pieces``."""
    points = np.unique(np.round(np.concatenate([[0.0, length], required]), 12))
    out = [points[0]]
    for lo, hi in zip(points[:-1], points[1:], strict=True):
        n = max(1, int(np.ceil((hi - lo) / (length / pieces) - 1e-9)))
        out += list(np.linspace(lo, hi, n + 1)[1:])
    return np.array(out)
