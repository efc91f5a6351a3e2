"""`eyesim grade`: grading submissions against a spec, locally or on a Dask cluster (docs/grading.md).

spec.py reads specs; submissions.py reads submissions; case_run.py grades one submission x case
in its own process (isolation.py), on executors.py's local pool or Dask; store.py keeps results
per case; summary.py, report_html.py and plots.py write the reports; grader.py ties them."""
