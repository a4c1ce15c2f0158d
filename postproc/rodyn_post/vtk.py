"""ParaView files written by hand (ASCII VTK XML, no vtk package needed).

`vtp_text` gives a PolyData file (.vtp) with one polyline per line, point data at the
nodes (the first array is the active scalars, a named one the active vectors) and the
line's index (deck order, from 0) as cell data; `pvd_text` a collection file (.pvd)
that makes a series of .vtp files a time series in ParaView.
"""
from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np


def _numbers(values) -> str:
    """Numbers separated by blanks, each with the digits that read back exactly."""
    return " ".join(repr(float(v)) for v in np.ravel(values))


def _array(name, values, components=1, kind="Float64", indent="        "):
    comp = f' NumberOfComponents="{components}"' if components != 1 else ""
    body = (" ".join(str(int(v)) for v in np.ravel(values)) if kind == "Int32"
            else _numbers(values))
    return (f'{indent}<DataArray type="{kind}" Name={quoteattr(name)}{comp} '
            f'format="ascii">{body}</DataArray>')


def vtp_text(polylines, point_data, time=None, vectors=None) -> str:
    """PolyData file text. polylines: [(n_i, 3) node positions] one per line;
    point_data: {name: [(n_i,) values per line]} (a name may carry components as
    [(n_i, c)]); time: written as the field data TimeValue; vectors: the name of the
    point data array that is the active vectors (None: no active vectors)."""
    points = np.vstack(polylines)
    sizes = [len(p) for p in polylines]
    offsets = np.cumsum(sizes)
    out = ['<?xml version="1.0"?>',
           '<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">',
           "  <PolyData>"]
    if time is not None:
        out += ["    <FieldData>",
                f'      <DataArray type="Float64" Name="TimeValue" NumberOfTuples="1" '
                f'format="ascii">{repr(float(time))}</DataArray>',
                "    </FieldData>"]
    out.append(f'    <Piece NumberOfPoints="{len(points)}" NumberOfVerts="0" '
               f'NumberOfLines="{len(polylines)}" NumberOfStrips="0" NumberOfPolys="0">')
    first = next(iter(point_data), None)
    active = (f" Scalars={quoteattr(first)}" if first else "") + (
        f" Vectors={quoteattr(vectors)}" if vectors else "")
    out.append(f"      <PointData{active}>")
    for name, parts in point_data.items():
        data = np.concatenate([np.asarray(p, float) for p in parts])
        out.append(_array(name, data, 1 if data.ndim == 1 else data.shape[1]))
    out += ["      </PointData>", '      <CellData Scalars="line_index">',
            _array("line_index", np.arange(len(polylines)), kind="Int32"),
            "      </CellData>", "      <Points>",
            _array("Points", points, 3), "      </Points>", "      <Lines>",
            _array("connectivity", np.arange(len(points)), kind="Int32"),
            _array("offsets", offsets, kind="Int32"), "      </Lines>", "    </Piece>",
            "  </PolyData>", "</VTKFile>", ""]
    return "\n".join(out)


def pvd_text(entries) -> str:
    """Collection file text; entries: [(time, file name relative to the .pvd)]."""
    out = ['<?xml version="1.0"?>',
           '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">',
           "  <Collection>"]
    for time, name in entries:
        out.append(f'    <DataSet timestep="{repr(float(time))}" group="" part="0" '
                   f"file={quoteattr(str(name))}/>")
    out += ["  </Collection>", "</VTKFile>", ""]
    return "\n".join(out)
