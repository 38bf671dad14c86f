"""ldfcz's Python tools as one package (tools/ldfcz_tools). The commands users run are thin scripts beside it,
tools/NAME.py, each calling ldfcz_tools.NAME.main(); tests and benchmarks import the modules (docs/tools.md).

  outputs          reading a run's outputs: JOB.summary.json, JOB.csv, JOB.sta, JOB.pvd (never JOB.log)
  peel_deck        the peel scenes' decks (paper sections 7-9)
  dcb_deck         double-cantilever-beam decks
  block_deck       the elastic block of the linear-algebra benchmarks and tests
  peel_study       the peel studies and their reports
  steady_force     the steady peel force of a force-displacement curve
  identify         identification of the interface parameters from a measured peel curve
  stability_suite  the stiff and extreme cases of decks/stability
  fuzz_decks       mutated decks: the reader must never crash
  locking_study    volumetric locking of the continuum elements
  orientation_newton_study, umat_step_study, plot_material   smaller studies and plots
"""
