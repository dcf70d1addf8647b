"""Parameter sweeps: a matrix of runs (cli), its spec, config copies, local and Slurm runs, the table."""
