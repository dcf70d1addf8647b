"""The twin's Python tools (scripts/twin is their one command-line entry):

  launch      args: the launch arguments of `twin run`, typed and range-checked;
              run_util: a launch file on its own ROS master (the tests' and the references' launcher)
  report      postprocess (summary.json, report.md, plots of a run), ledger, thermal, hybrid, diagnostics
  bags        reader (opening a bag, a message naming the file otherwise), plot, replay
  sweep       cli, spec, config_edit, run, slurm, table: parameter sweeps
  bench       cli, cosim, compare_engines, rates_config: the benchmarks
  viz         node, layout, markers: the live view in rviz
  references  the shipped missions against their stored summaries
  units       constants shared with the C++ models (src/common/units.hpp)
  console     the console filter of `twin run`
  paths       REPO, the checkout

Importable with PYTHONPATH=<repo>/python, or through the devel space (build/devel/setup.bash)."""
