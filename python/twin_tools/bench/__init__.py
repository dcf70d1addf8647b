"""The benchmarks of `twin bench` (cli) and their helpers."""
