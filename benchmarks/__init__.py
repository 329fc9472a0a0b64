"""Benchmarks and studies: scripts run as ``python benchmarks/NAME.py``; a package so that the suite
can import the test-sized subsets of a study (tests/fit/test_coverage.py) instead of loading files by path."""
