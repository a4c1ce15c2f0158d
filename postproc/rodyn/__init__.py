"""rodyn in process (docs/python.md): a mooring system read from a MoorDyn v2 input file
(or a rodyn deck with its *DYNAMIC), its statics solved and its dynamics stepped with prescribed motions of its coupled
points, its positions, tensions and forces read as numpy arrays, all through librodyn
(docs/capi.md) without a subprocess. ``rodyn.moordyn`` offers the function names of
MoorDyn's PyPI package over the same library.

    import rodyn
    with rodyn.System("lines.txt") as s:
        s.init()                      # the statics, coupled points where the file has them
        f = s.step(x, xd, 0.5)        # forces on the coupled points at t + 0.5 s
        xyz = s.line_nodes(1)         # (nodes, 3) positions of line 1
"""
import ctypes

import numpy as np

from ._lib import lib, doubles

__all__ = ["System", "RodynError"]


class RodynError(RuntimeError):
    """A librodyn call that did not succeed (its MoorDyn code in .code)."""

    def __init__(self, what, code):
        super().__init__(f"{what}: librodyn code {code}")
        self.code = code


def _ok(code, what):
    if code != 0:
        raise RodynError(what, code)


class System:
    """A mooring system of a MoorDyn v2 input file (or a rodyn deck), driven step by
    step."""

    def __init__(self, path):
        self._lib = lib()
        self._h = self._lib.MoorDyn_Create(str(path).encode())
        if not self._h:
            raise RodynError(f"{path} cannot be read (the message is on stderr)", -1)
        self.t = 0.0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        """Free the system (again: nothing)."""
        if self._h:
            self._lib.MoorDyn_Close(self._h)
            self._h = None

    def _count(self, fn):
        n = ctypes.c_uint(0)
        _ok(fn(self._h, ctypes.byref(n)), fn.__name__)
        return n.value

    @property
    def n_coupled(self):
        """Coupled degrees of freedom: 3 a Coupled (Vessel) point."""
        return self._count(self._lib.MoorDyn_NCoupledDOF)

    @property
    def n_lines(self):
        return self._count(self._lib.MoorDyn_GetNumberLines)

    @property
    def n_points(self):
        return self._count(self._lib.MoorDyn_GetNumberPoints)

    def point_position(self, k):
        """Position of point k (from 1) [m]."""
        pos = doubles(None, 3)
        _ok(self._lib.MoorDyn_GetPointPos(self._item("Point", k), pos), "GetPointPos")
        return np.array(pos[:])

    def point_type(self, k):
        """MoorDyn's type of point k: -1 coupled, 0 free, 1 fixed (or on a body)."""
        t = ctypes.c_int(0)
        _ok(self._lib.MoorDyn_GetPointType(self._item("Point", k), ctypes.byref(t)),
            "GetPointType")
        return t.value

    def coupled_positions(self):
        """Where the coupled points are, in the order of the coupled DOFs [m]."""
        ids = [k for k in range(1, self.n_points + 1) if self.point_type(k) == -1]
        if not ids:
            return np.zeros(0)
        return np.concatenate([self.point_position(k) for k in ids])

    def _item(self, kind, k):
        h = getattr(self._lib, f"MoorDyn_Get{kind}")(self._h, int(k))
        if not h:
            raise RodynError(f"no {kind.lower()} {k}", -6)
        return h

    def init(self, x=None, xd=None):
        """Coupled DOFs at x, the statics solved. Default: the coupled points where the
        file has them (a system with coupled bodies, 6 DOFs each first, needs x)."""
        if x is None:
            x = self.coupled_positions()
            if len(x) != self.n_coupled:
                raise RodynError("init: the system has coupled bodies; give x (each "
                                 "body's x, y, z, r, p, y, then the points' x, y, z)", -6)
        xd = np.zeros(len(x)) if xd is None else xd
        _ok(self._lib.MoorDyn_Init(self._h, doubles(x), doubles(xd)), "MoorDyn_Init")
        self.t = 0.0

    def step(self, x, xd, dt):
        """From the coupled points at x (now) with velocities xd, dt [s] on: the forces on
        them at the end [N], as an array."""
        n = self.n_coupled
        f = doubles(None, n)
        t = ctypes.c_double(self.t)
        h = ctypes.c_double(dt)
        _ok(self._lib.MoorDyn_Step(self._h, doubles(x), doubles(xd), f, ctypes.byref(t),
                                   ctypes.byref(h)), "MoorDyn_Step")
        self.t = t.value
        return np.array(f[:])

    def line_nodes(self, line):
        """(nodes, 3) positions of line (from 1) [m]."""
        return self._node_vectors(line, "MoorDyn_GetLineNodePos")

    def line_tensions(self, line):
        """(nodes, 3) MoorDyn's tension vectors of line's nodes [N] (docs/capi.md)."""
        return self._node_vectors(line, "MoorDyn_GetLineNodeTen")

    def record(self, path):
        """Append the nodes of every line now to the CSV file path (its header written
        when it is new): t_s, line, node, x_m, y_m, z_m, tension_N (MoorDyn's node tension,
        empty on a line it is not served on: docs/capi.md); values as Python writes them,
        to the last bit."""
        import csv
        import os
        new = not os.path.exists(path) or os.path.getsize(path) == 0
        with open(path, "a", newline="") as f:
            w = csv.writer(f)
            if new:
                w.writerow(["t_s", "line", "node", "x_m", "y_m", "z_m", "tension_N"])
            for line in range(1, self.n_lines + 1):
                xyz = self.line_nodes(line)
                try:
                    ten = np.linalg.norm(self.line_tensions(line), axis=1)
                except RodynError:
                    ten = [None] * len(xyz)
                for k, (x, tk) in enumerate(zip(xyz, ten)):
                    w.writerow([repr(self.t), line, k, *(repr(float(c)) for c in x),
                                "" if tk is None else repr(float(tk))])

    def _node_vectors(self, line, getter):
        h = self._item("Line", line)
        n = ctypes.c_uint(0)
        _ok(self._lib.MoorDyn_GetLineNumberNodes(h, ctypes.byref(n)), "GetLineNumberNodes")
        fn = getattr(self._lib, getter)
        out = np.zeros((n.value, 3))
        v = doubles(None, 3)
        for i in range(n.value):
            _ok(fn(h, i, v), getter)
            out[i] = v[:]
        return out
