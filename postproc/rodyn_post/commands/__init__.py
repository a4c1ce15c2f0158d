"""The commands of rodyn_post, one module each with main(argv=None) -> exit status, run
as the console commands of postproc/pyproject.toml or as `python3 -m
rodyn_post.commands.NAME`:

  rodyn-plot-static    plot_static    static shape, tension, moment (and the sea)
  rodyn-plot-dynamic   plot_dynamic   snapshots, support tensions, energy, momentum
  rodyn-plot-history   plot_history   time histories at places of a line
  rodyn-range-graph    range_graph    min / mean / max against arc length
  rodyn-animate        animate        GIF (and MP4) of the motion
  rodyn-paraview       to_paraview    ParaView .vtp / .pvd files
  rodyn-compare        compare        a result against another tool's CSV
  rodyn-plot-all       plot_all       every plot that applies to a results folder

Each uses the scaffold of rodyn_post.cli (arguments, messages, exit statuses of
rodyn_post.errors) and reads the results through rodyn_post's readers.
"""
