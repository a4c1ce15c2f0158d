"""Convert rodyn results to ParaView files (ASCII VTK XML; no vtk package needed).

    rodyn-paraview [RESULTS] [-o OUT_DIR] [--window T0 T1] [--every N]

RESULTS is a results folder (default: paper_case1), a dynamic.h5 or a results.h5 file.
Writes into OUT_DIR (default: RESULTS/paraview) and prints the paths of static.vtp and
dynamic.pvd:

  static.vtp            the static equilibrium, when the folder has static results
  dynamic.pvd           the time series (open this one in ParaView): one entry per frame
  dynamic_NNNNNN.vtp    one file per output frame (NNNNNN: frame number from 0), with
                        its time as the field data TimeValue

Every .vtp holds one polyline per line through its nodes (deck order; cell data
line_index from 0) with point data at the nodes, SI units:
  effective_tension_N      N3 (the active scalars)
  bending_moment_Nm        sqrt(M1^2 + M2^2)
  bending_curvature_per_m  sqrt(K1^2 + K2^2)
  torque_Nm                M3
  wall_tension_N           wall (true) tension (equal to the effective tension without
                           water)
  seabed_normal_N_per_m    seabed normal contact force per unit length (0 off the seabed)
  s_m                      unstretched arc length S from end A
rodyn computes the section results at the integration points: the values at a node are
linear in S between the two integration points around it, and at the nodes beyond the
outermost integration points (the ends) that point's value. Colour the lines by
effective_tension_N, add a Tube filter for thickness.

With *MODAL (the modes of rodyn_post.modes.load_modes), also:

  modes.pvd             the modes as a series (open this one in ParaView): entry k is
                        mode k, its time step the mode number
  mode_NNN.vtp          one file per mode (NNN: mode number from 1), the mode number as
                        the field data TimeValue

Every mode file holds the lines at their static equilibrium, with point data at the
nodes (the mode shape, scaled as rodyn writes it: the largest translation of the
system 1 m):
  displacement_magnitude   |translation| [m] (the active scalars)
  displacement             translation x, y, z [m] (the active vectors: Warp By Vector
                           with a scale factor draws the displaced shape)
  rotation                 rotation about x, y, z [rad] (0 at a cable's nodes)
  s_m                      unstretched arc length S from end A

Frames: those with T0 <= t <= T1 (default: all), every N-th (--every, default 1).
"""
import sys
from pathlib import Path

import numpy as np

from rodyn_post import cli, load_dynamic, load_modes, load_static
from rodyn_post.errors import InputError
from rodyn_post.quantities import check_window, point_values, resample_matrix, window_mask
from rodyn_post.vtk import pvd_text, vtp_text

PROG = "to_paraview"  # prefix of its messages
COMMAND = "rodyn-paraview"  # its console command (postproc/pyproject.toml)
STATIC_VTP = "static.vtp"
PVD = "dynamic.pvd"
MODES_PVD = "modes.pvd"
SECTION_ARRAYS = {"effective_tension_N": "tension", "bending_moment_Nm": "moment",
                  "bending_curvature_per_m": "curvature", "torque_Nm": "torque",
                  "wall_tension_N": "wall_tension"}
NODE_ARRAYS = {"seabed_normal_N_per_m": "seabed_normal"}   # results at the nodes
FRAME_ARRAYS = tuple(SECTION_ARRAYS) + tuple(NODE_ARRAYS)


def node_arrays(line):
    """{array name: values at the nodes} of a line: (n_frames, nn) for a dynamic line,
    (nn,) for a static one; s_m (last) is (nn,)."""
    arrays = {}
    weights = None
    for name, key in SECTION_ARRAYS.items():
        points, values = point_values(line, key)
        if weights is None:
            weights = resample_matrix(points, line.node_s)
        arrays[name] = values @ weights.T
    for name, key in NODE_ARRAYS.items():
        arrays[name] = point_values(line, key)[1]
    arrays["s_m"] = line.node_s
    return arrays


def static_vtp(results):
    """Text of static.vtp."""
    per_line = [node_arrays(line) for line in results.lines]
    data = {name: [a[name] for a in per_line] for name in per_line[0]}
    return vtp_text([line.node_xyz for line in results.lines], data)


def dynamic_files(results, frames):
    """(file name, time, text) of each frame's .vtp file, one after the other."""
    per_line = [node_arrays(line) for line in results.lines]
    for f in frames:
        data = {name: [a[name][f] for a in per_line] for name in FRAME_ARRAYS}
        data["s_m"] = [a["s_m"] for a in per_line]
        text = vtp_text([line.xyz(f) for line in results.lines], data, results.time[f])
        yield f"dynamic_{f:06d}.vtp", float(results.time[f]), text


def mode_files(modes):
    """(file name, mode number, text) of each mode's .vtp file, one after the other."""
    xyz = [line.node_xyz for line in modes.lines]
    for k in range(1, modes.n_modes + 1):
        moved = [line.translation[k - 1] for line in modes.lines]
        data = {"displacement_magnitude": [np.linalg.norm(u, axis=1) for u in moved],
                "displacement": moved,
                "rotation": [line.rotation[k - 1] for line in modes.lines],
                "s_m": [line.node_s for line in modes.lines]}
        yield f"mode_{k:03d}.vtp", k, vtp_text(xyz, data, k, vectors="displacement")


def parse_args(argv):
    parser = cli.make_parser(COMMAND, cli.help_text(__doc__), dpi=None,
                             results_help="results folder, dynamic.h5 or results.h5")
    cli.add_window(parser)
    parser.add_argument("--every", type=cli.positive_int, default=1, metavar="N",
                        help="write every N-th output frame (default: 1)")
    return cli.parse(parser, argv)


def main(argv=None):
    """Run the command line; returns the exit status."""
    args = parse_args(argv)

    def body():
        path = Path(args.results)
        if not path.exists():
            raise InputError(f"{path}: no such results folder")
        kinds = cli.result_kinds(path)
        if not kinds:
            raise InputError(f"{path}: no rodyn results here (neither results.h5, "
                             "static_nodes.csv, dynamic.h5 nor dynamic_nodes.csv)")
        dynamic = load_dynamic(path) if "dynamic" in kinds else None
        if dynamic is not None:
            check_window(dynamic, args.window)
            cli.warn_dynamic(PROG, dynamic)
        static = None
        if "static" in kinds or (dynamic is not None and "static" in
                                 cli.result_kinds(dynamic.folder)):
            static = load_static(path if "static" in kinds else dynamic.folder)
        folder = (dynamic or static).folder
        out = cli.output_dir(args, folder, None if args.out_dir else "paraview")
        if static is not None:
            print(cli.write_text(out / STATIC_VTP, static_vtp(static)))
            modes = load_modes(static.source if static.source.suffix == ".h5"
                               else static.folder)
            if modes is not None:
                entries = []
                for name, k, text in mode_files(modes):
                    cli.write_text(out / name, text)
                    entries.append((k, name))
                print(cli.write_text(out / MODES_PVD, pvd_text(entries)))
        if dynamic is not None:
            frames = np.flatnonzero(window_mask(dynamic.time, args.window))[::args.every]
            entries = []
            for name, time, text in dynamic_files(dynamic, frames):
                cli.write_text(out / name, text)
                entries.append((time, name))
            print(cli.write_text(out / PVD, pvd_text(entries)))
    return cli.run(PROG, body)


if __name__ == "__main__":
    sys.exit(main())
