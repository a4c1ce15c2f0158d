"""rodyn in process (package rodyn over librodyn; docs/python.md), on MoorDyn's
OC3-Hywind lines (tests/decks/good/moordyn/lines.txt): counts, the coupled points where
the file has them, the statics' forces kept by 10 steps at rest, the node arrays, and
errors raised, never a crash."""
import os

import numpy as np
import pytest

import rodyn
import rodyn.moordyn as md

LINES = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "decks", "good",
                     "moordyn", "lines.txt")


def test_system_at_rest():
    with rodyn.System(LINES) as s:
        assert (s.n_coupled, s.n_lines, s.n_points) == (9, 3, 6)
        x = s.coupled_positions()
        assert np.allclose(x[:3], [5.2, 0.0, -70.0], atol=0, rtol=0)
        s.init()
        f0 = s.step(x, np.zeros(9), 0.0)
        assert s.t == 0.0
        for _ in range(10):
            f = s.step(x, np.zeros(9), 0.5)
        assert s.t == pytest.approx(5.0, abs=1e-12)
        # the statics are the dynamics' rest
        assert np.max(np.abs(f - f0)) <= 1e-8 * np.max(np.abs(f0))
        # the lines pull the fairleads down and towards their anchors
        assert f0[0] > 0.0 and f0[2] < 0.0
        xyz = s.line_nodes(1)
        assert xyz.shape == (21, 3)
        assert np.allclose(xyz[-1], x[:3], atol=1e-9)
        ten = s.line_tensions(1)
        assert ten.shape == (21, 3) and np.linalg.norm(ten[-1]) > np.linalg.norm(ten[0])


def test_errors_raised():
    with pytest.raises(rodyn.RodynError):
        rodyn.System("no_such_file.txt")
    with rodyn.System(LINES) as s:
        with pytest.raises(rodyn.RodynError):   # a step before init
            s.step(np.zeros(9), np.zeros(9), 0.5)
        with pytest.raises(rodyn.RodynError):
            s.line_nodes(4)


def test_moordyn_names():
    h = md.Create(LINES)
    assert md.NCoupledDOF(h) == 9 and md.GetNumberLines(h) == 3
    x = [c for k in (4, 5, 6) for c in md.GetPointPos(md.GetPoint(h, k))]
    assert md.Init(h, x, [0.0] * 9) == 0
    f = md.Step(h, x, [0.0] * 9, 0.0, 0.5)
    assert len(f) == 9
    fh, fv, ah, av = md.GetFASTtens(h, 3)
    # a catenary at rest with no current: the same horizontal tension at both ends; the
    # anchor's vertical tension far below the fairlead's (the chain lies on the seabed)
    assert abs(fh[0] - ah[0]) <= 1e-6 * fh[0] and fv[0] > 100.0 * av[0]
    assert md.GetLineNumberNodes(md.GetLine(h, 1)) == 21
    assert md.GetPointType(md.GetPoint(h, 1)) == 1 and md.GetPointType(md.GetPoint(h, 4)) == -1
    assert md.Close(h) == 0
    assert md.Create("no_such_file.txt") is None
