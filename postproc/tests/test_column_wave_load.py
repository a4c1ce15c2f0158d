"""tools/column_wave_load.py, the strip-theory force RAOs of a vertical column (the rows
of *BODY WAVE LOAD): against the closed-form integrals of a uniform cylinder in water of
finite depth, a cone against a fine staircase of cylinders, the heading's rotation of
the force and moment, and the rows' layout."""
import importlib.util
import math
from pathlib import Path

import pytest

TOOL = Path(__file__).resolve().parents[2] / "tools" / "column_wave_load.py"
spec = importlib.util.spec_from_file_location("column_wave_load", TOOL)
cwl = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cwl)

RHO, G = 1025.0, 9.80665


@pytest.mark.parametrize("period", [5.0, 10.0, 25.0])
def test_uniform_cylinder_closed_form(period):
    d, length, dia, ca, depth = 0.0, 120.0, 9.4, 1.0, 320.0
    w = 2 * math.pi / period
    k = cwl.wave_number(w, depth)
    assert w**2 == pytest.approx(G * k * math.tanh(k * depth), rel=1e-14)
    area = math.pi * dia**2 / 4
    # int_{-L}^{0} cosh(k (z + d)) dz and int z cosh(k (z + d)) dz
    i0 = (math.sinh(k * depth) - math.sinh(k * (depth - length))) / k
    i1 = (length * math.sinh(k * (depth - length)) / k
          - (math.cosh(k * depth) - math.cosh(k * (depth - length))) / k**2)
    fh, mh, fz = cwl.column_loads([(d, -length, dia, dia)], period, depth, RHO, ca)
    c = (1 + ca) * RHO * w**2 * area / math.sinh(k * depth)
    assert fh == pytest.approx(c * i0, rel=1e-12)
    assert mh == pytest.approx(c * i1, rel=1e-12)
    assert fz == pytest.approx(RHO * G * area * math.cosh(k * (depth - length))
                               / math.cosh(k * depth), rel=1e-12)


def test_cone_against_staircase():
    """A cone widening downwards against 400 short cylinders: the same horizontal force
    and moment (the slices' areas) and vertical force (the steps' faces looking up)."""
    cone = [(0.0, -4.0, 6.5, 6.5), (-4.0, -12.0, 6.5, 9.4), (-12.0, -120.0, 9.4, 9.4)]
    n = 400
    stairs = [(0.0, -4.0, 6.5, 6.5)]
    for i in range(n):
        z1, z2 = -4.0 - 8.0 * i / n, -4.0 - 8.0 * (i + 1) / n
        dm = 6.5 + (9.4 - 6.5) * (i + 0.5) / n
        stairs.append((z1, z2, dm, dm))
    stairs.append((-12.0, -120.0, 9.4, 9.4))
    a = cwl.column_loads(cone, 10.0, 320.0, RHO, 1.0)
    b = cwl.column_loads(stairs, 10.0, 320.0, RHO, 1.0)
    for x, y in zip(a, b):
        assert x == pytest.approx(y, rel=1e-4)
    assert a[2] < 0.0        # the cone's slope looks up: the crest pushes the column down


def test_headings_and_phases():
    seg = "0,-4,6.5,6.5;-4,-12,6.5,9.4;-12,-120,9.4,9.4"
    segs = [tuple(float(v) for v in s.split(",")) for s in seg.split(";")]
    rows = cwl.rows(segs, [10.0], [0.0, 30.0, 90.0], 320.0, RHO, 1.0)
    fh, mh, fz = cwl.column_loads(segs, 10.0, 320.0, RHO, 1.0)
    r0, r30, r90 = rows
    assert r0[:2] == [10.0, 0.0] and len(r0) == 14
    assert r30[2] == pytest.approx(fh * math.cos(math.radians(30)), rel=1e-14)
    assert r30[3] == pytest.approx(fh * math.sin(math.radians(30)), rel=1e-14)
    assert r90[5] == pytest.approx(abs(mh), rel=1e-14)        # Mx = -M_h sin 90
    assert r0[6] == pytest.approx(abs(mh), rel=1e-14)         # My = M_h cos 0
    assert r0[8] == -90.0                     # the inertia force leads the crest
    assert r0[12] == 90.0                     # M_h < 0 (forces below R): opposite phase
    assert r0[4] == pytest.approx(abs(fz), rel=1e-14)
