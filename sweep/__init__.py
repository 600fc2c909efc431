"""Sweeps: one task kind over a grid of parameters, on Dask distributed.

``hexbot sweep SPEC.toml`` reads a sweep file (:mod:`.spec`), expands its
grid into pure tasks (:mod:`.kinds` says what each kind runs), runs them on
an embedded LocalCluster or any Dask scheduler (:mod:`.engine`), and
streams one row per finished task into a Parquet table (:mod:`.results`).
``hexbot sweep report RESULTS`` prints the summary tables (:mod:`.report`).
"""
